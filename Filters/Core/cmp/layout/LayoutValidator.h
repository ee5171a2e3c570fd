#pragma once
/// \file LayoutValidator.h
/// \brief An independent check that a patch layout on a surface is
///        topologically equivalent to its base domain. It shares no code with
///        the tracer (plain arrays in, a list of problems out), so tests and
///        users can trust it to judge the tracer's output.

#include <cmp/basedomain/BaseDomain.h>

#include <array>
#include <string>
#include <vector>

namespace cmp
{

/// \brief A labelled surface as the tracer outputs it.
struct LabelledSurface
{
  std::vector<std::array<double, 3>> points;   ///< Vertex positions.
  std::vector<std::array<int, 3>> triangles;   ///< Counter-clockwise triangles.
  std::vector<int> patchId;                    ///< Base triangle of each triangle.
  std::vector<int> featureId;                  ///< -1 or the landmark's feature, per vertex.
};

/// \brief The base domain: triangles over feature ids.
struct BaseTriangles
{
  std::vector<std::array<int, 3>> triangles; ///< Features of each base triangle, counter-clockwise.
};

/// \brief The base domain's triangles as feature ids.
BaseTriangles toBaseTriangles(const BaseDomain& domain);

/// \brief Returns every way `surface` fails to be a layout of `base`:
///        each patch must be a topological disk whose boundary passes through
///        exactly the three landmarks of its base triangle in the same cyclic
///        order; two patches share boundary edges exactly when their base
///        triangles share an edge, and then along one curve between the two
///        shared landmarks. Empty when the layout is valid.
std::vector<std::string> validateLayout(const LabelledSurface& surface, const BaseTriangles& base);

/// \brief The first problem `validateLayout()` finds in `surface` as a
///        layout of `domain`, "" when it is one: what a filter reports.
std::string layoutProblem(const LabelledSurface& surface, const BaseDomain& domain);

/// \brief Total area of the surface's triangles.
double totalArea(const LabelledSurface& surface);

} // namespace cmp
