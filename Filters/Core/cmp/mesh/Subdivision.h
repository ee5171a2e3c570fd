#pragma once
/// \file Subdivision.h
/// \brief 1-to-4 midpoint subdivision of a triangle mesh.

#include <cmp/mesh/TriangleMesh.h>

namespace cmp
{

/// \brief Splits every triangle into four at its edge midpoints, `levels`
///        times. Original vertices keep their indices (new ones are appended),
///        so landmark ids stay valid. The surface does not change shape.
TriangleMesh subdivideMidpoint(const TriangleMesh& mesh, int levels);

} // namespace cmp
