#pragma once
/// \file TriangleShape.h
/// \brief How well shaped triangles are: the one definition of the shape
///        quality and of the smallest angle that every stage reports or
///        optimizes (the base domain, straightening, fold repair, the
///        remesh).

#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief Shape quality of triangle (a, b, c): 4*sqrt(3)*area / sum of
///        squared edge lengths; 1 for an equilateral triangle, 0 for a
///        degenerate one (or one with a non-finite edge sum).
double triangleShapeQuality(const Vec3& a, const Vec3& b, const Vec3& c);

/// \brief `triangleShapeQuality()` signed by the triangle's orientation:
///        negative when its normal (counter-clockwise a, b, c) points
///        against `unitDirection`, which must be of length 1.
double signedTriangleShapeQuality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& unitDirection);

/// \brief Shape figures of a set of triangles.
struct TriangleShapeSummary
{
  double minimumAngleDegrees = 0.0; ///< Smallest corner angle of any triangle (180 with no triangle).
  double meanShapeQuality = 0.0;    ///< Mean `triangleShapeQuality()` (0 with no triangle).
};

/// \brief The smallest corner angle and the mean shape quality of
///        `triangles` over `points` (indices must be valid). Linear.
TriangleShapeSummary measureTriangleShapes(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);

} // namespace cmp
