#pragma once
/// \file MeshFile.h
/// \brief OFF, OBJ and PLY parsing and point welding, without VTK.
///
/// The readers take any file, including a damaged or hostile one: they fail
/// with a Status naming the file and line (the byte offset in binary PLY),
/// and never reserve memory for a count the file's size cannot hold.

#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace cmp
{

/// \brief Values per point or per triangle that a file carries besides its
///        geometry, under the file's name for them (PLY properties).
struct MeshFileProperty
{
  std::string name;           ///< The file's property name, for example `red` or `nx`.
  std::vector<double> values; ///< One value per file point, or per triangle.
};

/// \brief A surface as read from a file, before or after welding.
struct MeshFileData
{
  TriangleMesh mesh; ///< Positions and triangles (polygons fan-triangulated).
  /// \brief Texture coordinates of each triangle's three corners, when the
  ///        file has them for every face (OBJ `f v/vt`); otherwise empty.
  ///        Per corner, so texture seams need no duplicated points.
  std::vector<std::array<Eigen::Vector2d, 3>> cornerTexCoords;
  /// \brief For every point index in the file, the point it became after
  ///        welding. Landmark files index the file's points, so they are
  ///        mapped through this.
  std::vector<int> fileToMeshPoint;
  /// \brief PLY vertex scalar properties other than x, y and z, in the
  ///        file's order: one value per file point (index them as
  ///        `fileToMeshPoint` is indexed). Empty for OFF and OBJ.
  std::vector<MeshFileProperty> pointProperties;
  /// \brief PLY face scalar properties: one value per triangle, a polygon's
  ///        value on each of its triangles. Empty for OFF and OBJ.
  std::vector<MeshFileProperty> triangleProperties;
};

/// \brief Reads an OFF file (`OFF`, counts, points, polygons).
///
/// Fails (Status) on a missing, unreadable, binary or empty file, a first
/// line other than `OFF`, a count the rest of the file cannot hold (a point
/// takes at least six bytes, a face eight), a missing or malformed record,
/// and an index out of range. When the header claims more points than the
/// file lists, so that faces were read as points, the message says the
/// points are missing.
Status readOFF(const std::string& path, MeshFileData& out);

/// \brief Reads the `v`, `vt` and `f` records of an OBJ file.
///
/// OBJ has no counts: memory grows with the records actually read. Fails
/// (Status), naming the file and line, on a missing, unreadable or binary
/// file, a `v` or `vt` record without its coordinates, a face with fewer
/// than three vertices or referring to a vertex, texture coordinate or
/// normal (`vn`) not defined, an `l` or `p` record (not kept) referring to
/// a vertex or texture coordinate not defined, and a file with no `v` or
/// `f` record.
Status readOBJ(const std::string& path, MeshFileData& out);

/// \brief Reads a PLY file: ASCII, binary little or big endian, version 1.0.
///
/// Positions are the `vertex` element's scalar properties `x`, `y` and `z`
/// (any type, kept as the file's values: a `float` ASCII value is rounded to
/// float); triangles come from the `face` element's list property
/// `vertex_indices` (or `vertex_index`) of integer type, polygons
/// fan-triangulated, in the file's order. The vertex and face elements'
/// other scalar properties are kept in `pointProperties` and
/// `triangleProperties`; list properties and other elements are read by
/// their declared types and skipped.
///
/// Fails (Status), naming the file and the header or body line (the byte
/// offset in a binary file), on: a missing or unreadable file; a malformed
/// header (unknown keyword or type, no `end_header`, a property outside an
/// element, duplicate names); a missing `vertex` element or `x`, `y`, `z`;
/// a missing `face` element or index list; element counts the rest of the
/// file cannot hold; a record with too few or too many values, a value that
/// is not of its declared type or out of its range; a list count the file
/// cannot hold; a face with fewer than three vertices or an index out of
/// range; data after the last element.
Status readPLY(const std::string& path, MeshFileData& out);

/// \brief Merges points with identical coordinates and renumbers triangles.
///
/// Keeps the first occurrence's order so that an already welded file keeps
/// its point ids. Updates `fileToMeshPoint` (a map from file points to
/// current points; empty means the identity) and returns the number of
/// points removed.
/// O(n log n).
int weldIdenticalPoints(MeshFileData& data);

/// \brief Lower-cased extension of `path` without the dot ("" if none).
std::string fileExtension(const std::string& path);

} // namespace cmp
