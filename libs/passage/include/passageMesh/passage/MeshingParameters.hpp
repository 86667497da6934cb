#pragma once
// The meshing parameters (method.md section 1): what the tools choose and the policy's
// action. Lengths in metres. Read from system/meshDict.xml (docs/case-format.md).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace passageMesh {

// One row of the meshing-parameter table: everything that reads, writes, clips, searches or
// scales a parameter takes its name, range and kind from here.
struct MeshingParameterInfo {
  const char* name;
  double lower, upper;  // the method's range; in chords where `length`
  bool length;          // a length: metres in files, scaled by the chord
  bool integer;         // a count: rounded to the nearest integer
};

struct MeshingParameters {
  static constexpr int size = 10;
  // The method's eight (method.md section 1), first in the table: the policy's action and
  // what PassageSampler draws. The two after them (splitIn, splitOut) are this mesher's
  // own; at 0 they give the outer loop of the method's rule (docs/elliptic-smoothing.md).
  static constexpr int methodSize = 8;

  double yIn = 0;           // vertical offset of the periodic boundary at the inlet [m]
  double yOut = -0.01;      // ... at the outlet [m]
  double alphaCamber = 0.97;  // how much the periodic boundary follows the camber line
  double betaIn = 0.452;    // O/H interface position as a fraction of xIn
  double betaOut = 0.588;   // ... of xOut
  int nT = 372;             // O-block nodes around the blade
  double gammaLe = 3.1;     // node clustering towards the leading edge (0 = none)
  double gammaTe = 2.95;    // ... towards the trailing edge
  // Where the O-block's lower blade side hands over to the upper one on the inlet and
  // outlet interfaces: moved from the leading / trailing edge's height by this many
  // pitches (up > 0). Which wall nodes' lines reach the periodic segments follows from it.
  double splitIn = 0;
  double splitOut = 0;

  // The defaults of etc/meshDictDefaults.xml for a blade of the given chord (the member
  // initialisers above mirror that file for a chord of 1 m, where its lengths in chords
  // are metres; a test keeps the two equal).
  static MeshingParameters defaults(double chord);
  // In the order above; nT as a double.
  std::array<double, size> toArray() const;
  static MeshingParameters fromArray(const std::array<double, size>& v);  // nT rounded
  static const std::array<std::string, size>& names();
  // The table, in the order above: yIn, yOut in [-0.5C, 0.5C], alphaCamber [0, 1],
  // betaIn, betaOut [0.1, 0.9], nT [100, 1000], gammaLe, gammaTe [0, 5], splitIn,
  // splitOut [-0.5, 0.5] (pitches).
  static const std::array<MeshingParameterInfo, size>& table();
  // The range box for a chord C (lengths in metres).
  static std::array<double, size> lowerBounds(double chord);
  static std::array<double, size> upperBounds(double chord);
};

// Reads system/meshDict.xml. A missing file gives the defaults; a missing key takes its
// default; an unknown key or a malformed value is an InputError; a value outside the range
// box is clipped with a warning.
MeshingParameters readMeshDict(const std::filesystem::path& file, double chord,
                               std::vector<std::string>* warnings = nullptr);
// The meshDict.xml text (lengths in metres, 17 significant digits), and that text
// written atomically.
std::string meshDictXml(const MeshingParameters& p);
void writeMeshDict(const std::filesystem::path& file, const MeshingParameters& p);

}  // namespace passageMesh
