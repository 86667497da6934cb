#!/usr/bin/python3
"""Report of the T106A simpleFoam run (tutorials/T106A/Allrun.openfoam).

    /usr/bin/python3 openfoamReport.py [CASE]        CASE default: openfoam

Reads the function-object output of system/controlDict under CASE/postProcessing:
solverInfo (residuals), inletFlow/outletFlow (sum(phi)), outletFaces (face phi and U on
the outlet at the last write time), yPlus (blade). Prints the residual drops, the flows,
the mass-averaged exit flow angle sum(phi atan2(Uy, Ux)) / sum(phi) and the blade y+,
then the must-show criteria (docs/openfoam-t106a.md). Exit code 0 when all hold.
Standard library only (no numpy)."""
import math
import os
import sys

CASCADE_EXIT_ANGLE = 63.2      # deg, magnitude (T106A design exit flow angle)
MIN_ORDERS = 3.0
MAX_FLOW_DIFF_PERCENT = 0.5
MAX_ANGLE_DIFF = 2.0


def table(path):
    """Rows of a function-object .dat file and the names of its last '#' header."""
    names, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if words and words[0] == "Time":
                    names = words
            elif line.strip():
                rows.append(line.split())
    if not rows:
        sys.exit(f"{path}: no data")
    return names, rows


def latest(directory):
    times = [d for d in os.listdir(directory) if d.replace(".", "").replace("e", "").replace("-", "").isdigit()]
    return max(times, key=float)


def raw(path):
    """Values of a raw surface file: list of value tuples (coordinates dropped)."""
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            out.append([float(v) for v in line.split()[3:]])
    return out


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "openfoam"
    post = os.path.join(case, "postProcessing")
    ok = {}

    # Residuals: initial residual of the first and of the last iteration, final residual
    # (after the linear solve) of the last iteration.
    names, rows = table(os.path.join(post, "solverInfo", "0", "solverInfo.dat"))
    first, last = rows[0], rows[-1]
    print(f"simpleFoam iterations: {last[0]}")
    print("residuals                 first initial   last initial   last final   orders fallen")
    worst = math.inf
    for i, name in enumerate(names):
        if not name.endswith("_initial"):
            continue
        field = name[: -len("_initial")]
        r0, r1 = float(first[i]), float(last[i])
        rf = float(last[names.index(field + "_final")])
        orders = math.log10(r0 / r1) if r1 > 0 else math.inf
        worst = min(worst, orders)
        print(f"  {field:<8}                {r0:12.4e}   {r1:12.4e}  {rf:11.4e}   {orders:6.2f}")
    ok["residuals fall >= 3 orders (every field)"] = worst >= MIN_ORDERS

    # Flow through inlet and outlet: sum(phi) [m3/s over the mesh span; rho = 1].
    qIn = float(table(os.path.join(post, "inletFlow", "0", "surfaceFieldValue.dat"))[1][-1][1])
    qOut = float(table(os.path.join(post, "outletFlow", "0", "surfaceFieldValue.dat"))[1][-1][1])
    diff = 100.0 * (qOut + qIn) / abs(qIn)
    print(f"flow sum(phi): inlet {qIn:.8e}  outlet {qOut:.8e} m3/s (rho = 1: kg/s)  "
          f"difference {diff:+.4f} % of inlet")
    ok["inlet/outlet flow within 0.5 %"] = abs(diff) <= MAX_FLOW_DIFF_PERCENT

    # Exit flow angle on the outlet, phi-weighted, at the last write time.
    surface = os.path.join(post, "outletFaces", "surface")
    t = latest(surface)
    phi = [v[0] for v in raw(os.path.join(surface, t, "phi_patch_outlet.raw"))]
    U = raw(os.path.join(surface, t, "U_patch_outlet.raw"))
    if len(phi) != len(U):
        sys.exit("outletFaces: phi and U face counts differ")
    angles = [math.degrees(math.atan2(u[1], u[0])) for u in U]
    back = sum(1 for p in phi if p < 0)
    mass = sum(p * a for p, a in zip(phi, angles)) / sum(phi)
    ux = sum(p * u[0] for p, u in zip(phi, U)) / sum(phi)
    uy = sum(p * u[1] for p, u in zip(phi, U)) / sum(phi)
    print(f"exit flow angle at the outlet (time {t}, {len(phi)} faces, {back} with backflow): "
          f"mass-averaged {mass:.3f} deg; angle of the mass-averaged velocity "
          f"{math.degrees(math.atan2(uy, ux)):.3f} deg; cascade {CASCADE_EXIT_ANGLE} deg "
          f"(magnitude), difference {abs(mass) - CASCADE_EXIT_ANGLE:+.3f} deg")
    ok["exit angle within 2 deg of 63.2"] = abs(abs(mass) - CASCADE_EXIT_ANGLE) <= MAX_ANGLE_DIFF

    # Blade y+ (yPlus function object: min, max, face average) at the last write time.
    names, rows = table(os.path.join(post, "yPlus", "0", "yPlus.dat"))
    blade = [r for r in rows if r[1] == "blade"][-1]
    print(f"blade y+ (time {blade[0]}): min {float(blade[2]):.4f}  mean {float(blade[4]):.4f}  "
          f"max {float(blade[3]):.4f}")
    ok["y+ reported"] = True

    for what, good in ok.items():
        print(f"{'PASS' if good else 'FAIL'}  {what}")
    return 0 if all(ok.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
