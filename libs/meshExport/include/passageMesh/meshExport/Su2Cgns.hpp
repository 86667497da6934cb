#pragma once
// The passage for SU2: one unstructured CGNS zone (SU2 reads no multi-block or structured
// CGNS) and a config fragment with the markers (docs/case-format.md).
//
// CGNS: base "Base" (2-D, SI units), zone "passage" (Unstructured) with CoordinateX/Y, an
// element section "cells" (QUAD_4, counterclockwise) and one BAR_2 section per patch named
// by the patch (blade, inlet, outlet, periodicLower, periodicUpper: SU2's marker names),
// element numbers running on from the cells. SU2 takes the periodic pairing from its
// config, not from the CGNS file: the fragment holds MARKER_PERIODIC with the
// translation lower -> upper. For other readers the zone also holds the pair in CGNS's
// own form: a connection "periodic" (Abutting1to1, vertex PointList of periodicLower to
// PointListDonor of periodicUpper in the same zone) whose periodic property is that
// translation (float32, as CGNS stores it).
#include <filesystem>
#include <string>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/meshExport/UnstructuredPassage.hpp"

namespace passageMesh {

// The writer of `file` for writeFilesAtomically or StagedOutputs::write (it refers to
// `passage`, which must outlive it); its errors name `file` and the CGNS error. Not
// thread-safe: the CGNS library has global state.
FileWriter su2CgnsFileWriter(const UnstructuredPassage& passage, const std::filesystem::path& file);
FileWriter su2CgnsFileWriter(const UnstructuredPassage&& passage, const std::filesystem::path& file) = delete;

// Writes `file` through a temporary renamed over it; throws std::runtime_error naming the
// file when it cannot.
void writeSu2Cgns(const UnstructuredPassage& passage, const std::filesystem::path& file);

// MARKER_PERIODIC, MARKER_HEATFLUX (adiabatic walls), MARKER_INLET/OUTLET name lists as
// comments for the user to complete, MESH_FILENAME and MESH_FORMAT= CGNS.
std::string su2ConfigFragment(const UnstructuredPassage& passage, const std::string& meshFileName);

}  // namespace passageMesh
