#pragma once
/// \file Landmarks.h
/// \brief Landmark files and the `FeatureId` convention.
///
/// A landmark set is the list of mesh vertices that carry features
/// 0..F-1, in feature order: the paper's F feature points (§2, "Basic
/// Setup"). On a surface it is stored as the point array
/// `FeatureId`: -1 everywhere except at the F landmark vertices.

#include <cmp/io/MeshFile.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace cmp
{

/// \brief Landmark vertex of each feature: `vertexOfFeature[f]` is the mesh
///        vertex that carries feature f, or `kMissingLandmark` for a
///        feature that could not be placed on this model (beyond the
///        paper, whose every model has every feature point).
using LandmarkList = std::vector<int>;

/// \brief The vertex id of a feature missing on a model, in a
///        `LandmarkList` and in every landmark file format.
constexpr int kMissingLandmark = -1;

/// \brief How many features of `landmarks` are missing.
int missingLandmarkCount(const LandmarkList& landmarks);

/// \brief Reads a landmark file and returns mesh vertex ids in feature order.
///
/// The format follows the extension:
/// - `.vts`: `vertex_id x y z` per line; the coordinates must match the
///   vertex (catches a landmark file paired with the wrong mesh);
/// - `.csv`: `x,y,z` per row (an optional header row is skipped), each
///   snapped to the nearest vertex;
/// - anything else (`.pinned`, `.txt`, ...): `lk ID` or `ID` per line.
///
/// A feature that could not be placed on this model is `kMissingLandmark`:
/// a `.vts` line `-1` (the rest of the line ignored), `lk -1` or `-1`, a
/// `.csv` row `nan,nan,nan` or an empty row before the last landmark.
///
/// Ids are 0-based indices into the file's own point list; `fileToMeshPoint`
/// (from `MeshFileData`, may be empty for identity) maps them to the welded
/// mesh. `#` starts a comment.
///
/// \pre `fileToMeshPoint` is empty or maps every file point to a vertex of
///      `mesh`.
/// Fails (Status), naming the file and line, on a missing, unreadable or
/// binary file, a malformed line or a field too many, an id out of range, a
/// `.vts` position farther than 0.1% of the bounding-box diagonal from its
/// vertex, a `.csv` position farther than 5% of it from every vertex or
/// only partly `nan`, a file without landmarks or with every one missing,
/// and two features on one vertex.
Status readLandmarkFile(const std::string& path, const TriangleMesh& mesh, const std::vector<int>& fileToMeshPoint,
  LandmarkList& landmarks);

/// \brief The text of a landmark file for `landmarks` on `mesh`, in the
///        format `readLandmarkFile` reads for `path`'s extension (`.vts`:
///        `id x y z`, `.csv`: a header row then `x,y,z`, else `lk id`), so
///        that reading it back gives the same landmarks.
///
/// `fileToMeshPoint` (may be empty for identity) is the same map the reader
/// takes: ids are written as the first file point of each mesh vertex, so
/// the file pairs with the original mesh file even when points were welded.
/// Fails (Status) on an empty or invalid landmark list
/// (`validateLandmarks()`) and on a landmark vertex no file point maps to.
Status formatLandmarkFile(const std::string& path, const LandmarkList& landmarks, const TriangleMesh& mesh,
  const std::vector<int>& fileToMeshPoint, std::string& text);

/// \brief Writes `formatLandmarkFile`'s text to `path`. Fails (Status,
///        "PATH: ...") where `formatLandmarkFile` fails and when the file
///        cannot be written.
Status writeLandmarkFile(const std::string& path, const LandmarkList& landmarks, const TriangleMesh& mesh,
  const std::vector<int>& fileToMeshPoint);

/// \brief Checks that every landmark is a valid vertex (or, with
///        `allowMissing`, `kMissingLandmark`), no vertex carries two
///        features, and (when `expectedCount >= 0`) that there are exactly
///        `expectedCount` of them. Fails (Status) on the first of these
///        that does not hold, naming the landmark; a missing one without
///        `allowMissing` says that it is missing.
Status validateLandmarks(
  const LandmarkList& landmarks, int vertexCount, int expectedCount = -1, bool allowMissing = false);

/// \brief The per-vertex `FeatureId` values for a landmark list (a missing
///        feature is on no vertex).
/// \pre `landmarks` pass `validateLandmarks(landmarks, vertexCount, -1, true)`.
std::vector<int> featureIdsOf(const LandmarkList& landmarks, int vertexCount);

/// \brief Reads landmarks back from per-vertex `FeatureId` values, checking
///        that they are -1 or 0..F-1 and that each feature occurs exactly once.
///        F is `featureCount` when given (>= 0; the field data
///        `FeatureCount` of a surface whose last features may be missing),
///        else the largest id plus one. Fails (Status) on a value below -1,
///        not below the vertex count or not below `featureCount`, on no
///        landmark at all, on a feature on two vertices, and, unless
///        `allowMissing` (it is then `kMissingLandmark`), on a feature that
///        is on no vertex.
Status landmarksFromFeatureIds(
  const std::vector<int>& featureIds, LandmarkList& landmarks, int featureCount = -1, bool allowMissing = false);

} // namespace cmp
