#include <cmp/map/PatchParameterization.h>

#include <cmp/numerics/MeanValueSystem.h>
#include <cmp/numerics/SymmetricDirichletRelaxation.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cmp
{

bool coordinatesInTriangle(const BaseDomain& domain, int from, const std::array<double, 3>& coordinates, int to,
  std::array<double, 3>& result)
{
  const Triangle& source = domain.mesh.triangles[from];
  const Triangle& target = domain.mesh.triangles[to];
  result = { 0.0, 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
  {
    if (coordinates[k] == 0.0)
      continue;
    const auto it = std::find(target.begin(), target.end(), source[k]);
    if (it == target.end())
      return false;
    result[it - target.begin()] = coordinates[k];
  }
  return true;
}

namespace
{

/// Fills `values` (barycentric in `corners` order) for the curve vertices of
/// the patch with corners a, b, c: each side by arc length.
void boundaryCoordinates(const TracedNet& net, const BaseTopology& base, const Triangle& corners,
  std::vector<int>& fixedRow, std::vector<std::array<double, 3>>& fixedValues, std::vector<int>& boundary)
{
  for (int k = 0; k < 3; ++k)
  {
    const int a = corners[k], b = corners[(k + 1) % 3];
    const int e = base.edgeBetween(a, b);
    std::vector<int> curve = net.curves[e];
    if (base.edges[e][0] != a)
      std::reverse(curve.begin(), curve.end());
    const std::vector<double> along = arcLengthParameters(net.mesh, curve);
    for (std::size_t i = 0; i + 1 < curve.size(); ++i)
    {
      std::array<double, 3> value{ 0.0, 0.0, 0.0 };
      value[k] = 1.0 - along[i];
      value[(k + 1) % 3] = along[i];
      fixedRow[curve[i]] = static_cast<int>(fixedValues.size());
      fixedValues.push_back(value);
      boundary.push_back(curve[i]);
    }
  }
}

/// Reweightings of a crowded patch at most.
constexpr int kMaximumStretchIterations = 30;
/// A patch whose smallest triangle has less than this share of its
/// parameter area, relative to its share of the surface area, is crowded.
constexpr double kCrowded = 1e-4;
/// Per-triangle squared stretch counted at most (a crushed or flipped
/// triangle), so one triangle cannot make every map look equally bad.
constexpr double kSquaredStretchCap = 1e16;

/// Surface area of every triangle of a patch, and their sum.
struct PatchAreas
{
  std::vector<double> triangle;
  double total = 0.0;

  explicit PatchAreas(const TriangleMesh& piece)
  {
    triangle.resize(piece.triangleCount());
    for (int t = 0; t < piece.triangleCount(); ++t)
      total += triangle[t] = triangleArea(piece, t);
  }
};

/// Share of the base triangle's area that triangle `tri`'s image takes
/// (the base triangle has 1), signed: <= 0 if flipped.
double imageShare(const Triangle& tri, const Eigen::MatrixXd& barycentric)
{
  const Eigen::Vector2d e1 = barycentric.row(tri[1]) - barycentric.row(tri[0]);
  const Eigen::Vector2d e2 = barycentric.row(tri[2]) - barycentric.row(tri[0]);
  return cross2(e1, e2);
}

/// min over triangles of (share of the base triangle's area) / (share of
/// the patch's surface area): 1 for an area-preserving map, <= 0 if flipped.
double smallestAreaRatio(const TriangleMesh& piece, const PatchAreas& areas, const Eigen::MatrixXd& barycentric)
{
  double smallest = std::numeric_limits<double>::infinity();
  for (int t = 0; t < piece.triangleCount(); ++t)
    smallest = std::min(smallest,
      imageShare(piece.triangles[t], barycentric) * areas.total / std::max(areas.triangle[t], 1e-300));
  return smallest;
}

/// The base triangle drawn equilateral with the patch's surface area, as a
/// map from barycentric coordinates (of corners B and C) to the plane: its
/// columns are corners B and C, corner A at the origin.
Eigen::Matrix2d equilateralFrame(const PatchAreas& areas)
{
  const double side = std::sqrt(4.0 * areas.total / std::sqrt(3.0));
  Eigen::Matrix2d frame;
  frame << side, 0.5 * side, 0.0, 0.5 * std::sqrt(3.0) * side;
  return frame;
}

/// Per triangle, the square of Sander's L2 stretch of the map from the
/// base triangle (drawn equilateral with the patch's area) to the surface:
/// 1 for an isometry, large where a protrusion crowds; capped, and the cap
/// for a crushed or flipped triangle.
Eigen::VectorXd squaredTriangleStretch(const TriangleMesh& piece, const PatchAreas& areas,
  const Eigen::MatrixXd& barycentric)
{
  const Eigen::Matrix2d frame = equilateralFrame(areas);
  const auto plane = [&](int v) -> Eigen::Vector2d { return frame * barycentric.row(v).transpose(); };
  Eigen::VectorXd result(piece.triangleCount());
  for (int t = 0; t < piece.triangleCount(); ++t)
  {
    const Triangle& tri = piece.triangles[t];
    const Eigen::Vector2d q1 = plane(tri[0]), q2 = plane(tri[1]), q3 = plane(tri[2]);
    const Vec3 &p1 = piece.points[tri[0]], &p2 = piece.points[tri[1]], &p3 = piece.points[tri[2]];
    const double twiceArea = (q2.x() - q1.x()) * (q3.y() - q1.y()) - (q3.x() - q1.x()) * (q2.y() - q1.y());
    result[t] = kSquaredStretchCap;
    if (twiceArea > 0.0)
    {
      const Vec3 ss = (p1 * (q2.y() - q3.y()) + p2 * (q3.y() - q1.y()) + p3 * (q1.y() - q2.y())) / twiceArea;
      const Vec3 st = (p1 * (q3.x() - q2.x()) + p2 * (q1.x() - q3.x()) + p3 * (q2.x() - q1.x())) / twiceArea;
      result[t] = std::min(kSquaredStretchCap, 0.5 * (ss.squaredNorm() + st.squaredNorm()));
    }
  }
  return result;
}

/// The L2 stretch of each vertex (area-weighted over its triangles), at
/// least 1: crowded vertices get a large value.
Eigen::VectorXd vertexStretch(const TriangleMesh& piece, const PatchAreas& areas, const Eigen::MatrixXd& barycentric)
{
  const Eigen::VectorXd squared = squaredTriangleStretch(piece, areas, barycentric);
  Eigen::VectorXd weighted = Eigen::VectorXd::Zero(piece.vertexCount()), sum = weighted;
  for (int t = 0; t < piece.triangleCount(); ++t)
    for (int v : piece.triangles[t])
    {
      weighted[v] += areas.triangle[t] * squared[t];
      sum[v] += areas.triangle[t];
    }
  Eigen::VectorXd result(piece.vertexCount());
  for (int v = 0; v < piece.vertexCount(); ++v)
    result[v] = sum[v] > 0.0 ? std::max(1.0, std::sqrt(weighted[v] / sum[v])) : 1.0;
  return result;
}

/// Spreads a crowded patch: lowers the weights towards stretched vertices
/// (Yoshizawa, Belyaev, Seidel 2004) and keeps the least crowded map.
/// Weights spanning many orders of magnitude make late iterations unstable,
/// hence the cap, the patience and keeping the best map.
void spreadCrowded(const TriangleMesh& piece, const PatchAreas& areas,
  Eigen::SparseMatrix<double> weights, const std::vector<int>& fixedRow, const Eigen::MatrixXd& fixedValues,
  Eigen::MatrixXd& values)
{
  double crowding = smallestAreaRatio(piece, areas, values);
  if (!(crowding < kCrowded))
    return;
  Eigen::MatrixXd relaxed = values;
  for (int iteration = 0, idle = 0; iteration < kMaximumStretchIterations && crowding < kCrowded && idle < 4;
       ++iteration, ++idle)
  {
    weights = weights * vertexStretch(piece, areas, relaxed).cwiseInverse().asDiagonal();
    if (!solveConvexCombinationSystem(weights, fixedRow, fixedValues, relaxed).ok())
      break;
    const double relaxedCrowding = smallestAreaRatio(piece, areas, relaxed);
    if (relaxedCrowding > crowding)
    {
      crowding = relaxedCrowding;
      values = relaxed;
      idle = -1;
    }
  }
}

/// Lowers the distortion of any patch's map (`lowerStretch`): symmetric
/// Dirichlet relaxation in the plane, the base triangle drawn equilateral
/// with the patch's surface area so that an isometry is the energy's
/// minimum. Kept only if no triangle flipped on the way back to
/// barycentric coordinates; otherwise the patch keeps the map it had, which
/// is bijective too.
void lowerStretch(const TriangleMesh& piece, const PatchAreas& areas, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values)
{
  if (!(areas.total > 0.0))
    return; // no frame to relax in
  const Eigen::Matrix2d frame = equilateralFrame(areas);
  Eigen::MatrixXd plane = values * frame.transpose();
  std::vector<char> fixed(fixedRow.size());
  for (std::size_t v = 0; v < fixedRow.size(); ++v)
    fixed[v] = fixedRow[v] >= 0;
  if (!relaxSymmetricDirichlet(piece, fixed, plane).ok())
    return;
  Eigen::MatrixXd relaxed = plane * frame.transpose().inverse();
  for (int v = 0; v < relaxed.rows(); ++v)
    if (fixedRow[v] >= 0) // the curves' exact values, not their round trip through the plane
      relaxed.row(v) = fixedValues.row(fixedRow[v]);
  if (relaxed.allFinite() && smallestAreaRatio(piece, areas, relaxed) > 0.0)
    values.swap(relaxed);
}

} // namespace

Status parameterizePatches(const TracedNet& net, const BaseDomain& domain, PatchParameterization& out,
  const PatchParameterizationOptions& options)
{
  const EditableMesh& mesh = net.mesh;
  const int patchCount = domain.mesh.triangleCount();
  BaseTopology base;
  base.build(domain);
  std::vector<std::vector<int>> trianglesOf(patchCount);
  for (int t = 0; t < mesh.triangleCount(); ++t)
    trianglesOf[net.patchOfTriangle[t]].push_back(t);

  out = PatchParameterization{};
  out.baseTriangle.assign(mesh.vertexCount(), -1);
  out.baseCoordinates.assign(mesh.vertexCount(), { 0.0, 0.0, 0.0 });
  out.smallestRelativeArea = 1.0;
  out.smallestAreaRatio = std::numeric_limits<double>::infinity();
  std::vector<int> local(mesh.vertexCount(), -1), globalFixedRow(mesh.vertexCount(), -1);
  for (int patch = 0; patch < patchCount; ++patch)
  {
    std::vector<std::array<double, 3>> boundaryValues;
    std::vector<int> boundary;
    boundaryCoordinates(net, base, domain.mesh.triangles[patch], globalFixedRow, boundaryValues, boundary);

    std::vector<int> global;
    const TriangleMesh piece = extractTriangles(mesh, trianglesOf[patch], local, global);
    const PatchAreas areas(piece);
    std::vector<int> fixedRow(global.size(), -1);
    for (std::size_t i = 0; i < global.size(); ++i)
      fixedRow[i] = globalFixedRow[global[i]];
    Eigen::MatrixXd fixedValues(boundaryValues.size(), 2), values;
    for (std::size_t r = 0; r < boundaryValues.size(); ++r)
      fixedValues.row(r) << boundaryValues[r][1], boundaryValues[r][2];
    Eigen::SparseMatrix<double> weights = meanValueWeights(piece);
    if (Status s = solveConvexCombinationSystem(weights, fixedRow, fixedValues, values); !s.ok())
      return Status::error("patch " + std::to_string(patch) + ": " + s.message());
    // Landmark-free protrusions (tails, ears) crowd exponentially in a mean
    // value map, down to zero area in double precision, and uniform remesh
    // samples then miss them.
    spreadCrowded(piece, areas, std::move(weights), fixedRow, fixedValues, values);
    if (options.lowerStretch)
      lowerStretch(piece, areas, fixedRow, fixedValues, values);
    const double crowding = smallestAreaRatio(piece, areas, values);
    out.smallestAreaRatio = std::min(out.smallestAreaRatio, crowding);

    for (const Triangle& tri : piece.triangles)
    {
      const double relativeArea = imageShare(tri, values);
      out.smallestRelativeArea = std::min(out.smallestRelativeArea, relativeArea);
      if (!(relativeArea > 0.0))
        ++out.flippedTriangles;
    }
    for (std::size_t i = 0; i < global.size(); ++i)
    {
      const int v = global[i];
      if (out.baseTriangle[v] < 0) // patches in increasing order: shared vertices keep the lowest
      {
        out.baseTriangle[v] = patch;
        out.baseCoordinates[v] = fixedRow[i] >= 0 // exact zeros on the curves
          ? boundaryValues[fixedRow[i]]
          : std::array<double, 3>{ 1.0 - values(i, 0) - values(i, 1), values(i, 0), values(i, 1) };
      }
      local[v] = -1;
    }
    for (int v : boundary)
      globalFixedRow[v] = -1;
  }
  return {};
}

} // namespace cmp
