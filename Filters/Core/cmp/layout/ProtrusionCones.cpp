#include <cmp/layout/ProtrusionCones.h>

#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/EdgePaths.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace cmp
{

namespace
{

Status checkOptions(const ProtrusionConeOptions& o)
{
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(o.leastDepth) || !positive(o.peakRadius) || !positive(o.ballRadius) ||
    !positive(o.largestBallShare))
    return Status::error("protrusion cones: leastDepth, peakRadius, ballRadius and largestBallShare must be "
                         "positive and finite");
  if (o.ballScales < 1 || o.ballScales > 8)
    return Status::error("protrusion cones: ballScales must be 1 to 8, not " + std::to_string(o.ballScales));
  if (o.leastModels < 1)
    return Status::error("protrusion cones: leastModels must be at least 1, not " + std::to_string(o.leastModels));
  return {};
}

/// Per vertex, a third of the area of its triangles.
std::vector<double> vertexAreas(const TriangleMesh& surface)
{
  std::vector<double> area(surface.points.size(), 0.0);
  for (int t = 0; t < surface.triangleCount(); ++t)
    for (int v : surface.triangles[t])
      area[v] += triangleArea(surface, t) / 3.0;
  return area;
}

/// Whether the landmarks (`isLandmark`) outside the ball of `radius` round a
/// tip (`ball`: distances from it, infinite beyond the largest radius
/// asked) all lie in one piece of the surface outside it: a ball round the
/// tip of a landmark-free protrusion caps it, one round the middle of a
/// leg or tail with a landmark at its end leaves that landmark apart.
bool capsSurface(const EdgeGraph& graph, const std::vector<double>& ball, double radius,
  const std::vector<char>& isLandmark)
{
  const int n = graph.vertexCount();
  std::vector<char> seen(n, 0);
  int pieces = 0;
  std::vector<int> stack;
  for (int s = 0; s < n; ++s)
  {
    if (!isLandmark[s] || seen[s] || ball[s] <= radius)
      continue;
    if (++pieces > 1)
      return false;
    seen[s] = 1;
    stack.assign(1, s);
    while (!stack.empty())
    {
      const int v = stack.back();
      stack.pop_back();
      for (int a = graph.first[v]; a < graph.first[v + 1]; ++a)
      {
        const int u = graph.to[a];
        if (!seen[u] && !(ball[u] <= radius))
        {
          seen[u] = 1;
          stack.push_back(u);
        }
      }
    }
  }
  return true;
}

} // namespace

Status findProtrusions(const TriangleMesh& surface, const LandmarkList& landmarks,
  std::vector<Protrusion>& protrusions, const ProtrusionConeOptions& options)
{
  protrusions.clear();
  if (Status s = checkOptions(options); !s.ok())
    return s;
  if (surface.vertexCount() == 0 || surface.triangleCount() == 0)
    return Status::error("protrusion cones: the surface is empty");
  if (landmarks.empty())
    return Status::error("protrusion cones: there are no landmarks");
  if (Status s = validateLandmarks(landmarks, surface.vertexCount()); !s.ok())
    return Status::error("protrusion cones: " + s.message());
  const double unit = std::sqrt(surfaceArea(surface));
  if (!(unit > 0.0))
    return Status::error("protrusion cones: the surface has no area");
  // On a surface with boundaries no tip lies on a boundary: a landmark
  // there would be a boundary landmark, which L0 has only on its holes.
  std::vector<char> onBoundary;
  if (Status s = boundaryVertices(surface, onBoundary); !s.ok())
    return Status::error("protrusion cones: " + s.message());
  const EdgeGraph graph = edgeGraph(surface);
  const int n = graph.vertexCount();
  std::vector<int> parent;
  const std::vector<double> depth = edgePathDistances(graph, landmarks, std::numeric_limits<double>::infinity(), &parent);
  // The landmark each vertex is nearest to: the start of its shortest path.
  std::vector<int> root(n, -1);
  for (int v = 0; v < n; ++v)
  {
    int u = v;
    std::vector<int> path;
    while (root[u] < 0 && parent[u] >= 0)
    {
      path.push_back(u);
      u = parent[u];
    }
    const int r = root[u] >= 0 ? root[u] : (parent[u] < 0 && std::isfinite(depth[u]) ? u : -1);
    root[u] = r;
    for (int w : path)
      root[w] = r;
  }
  std::map<int, int> featureOf;
  std::vector<char> isLandmark(n, 0);
  for (std::size_t f = 0; f < landmarks.size(); ++f)
  {
    featureOf[landmarks[f]] = static_cast<int>(f);
    isLandmark[landmarks[f]] = 1;
  }
  const std::vector<double> area = vertexAreas(surface);

  // Local maxima of the distance from the landmarks, deepest first.
  std::vector<int> candidates;
  for (int v = 0; v < n; ++v)
  {
    if (!std::isfinite(depth[v]) || depth[v] < options.leastDepth * unit || onBoundary[v])
      continue;
    bool highest = true;
    for (int a = graph.first[v]; a < graph.first[v + 1] && highest; ++a)
      highest = depth[graph.to[a]] <= depth[v];
    if (highest)
      candidates.push_back(v);
  }
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) { return depth[a] > depth[b]; });
  std::vector<char> taken(n, 0); // within the peak radius of a tip kept, or the ball of a protrusion found
  for (int v : candidates)
  {
    if (taken[v])
      continue;
    const std::vector<double> near = edgePathDistances(graph, { v }, options.peakRadius * unit);
    bool peak = true;
    for (int u = 0; u < n && peak; ++u)
      peak = !std::isfinite(near[u]) || depth[u] <= depth[v];
    if (!peak)
      continue;
    for (int u = 0; u < n; ++u)
      if (std::isfinite(near[u]))
        taken[u] = 1;
    if (root[v] < 0)
      continue;
    // The balls of radius r, 2r, 4r, ... (the larger ones as far as half
    // the tip's depth, so that they stay on the protrusion): the first that
    // holds less than the share and caps the surface (the landmarks
    // outside it all in one piece) makes the peak a protrusion.
    const double smallest = options.ballRadius * unit;
    int scales = 1;
    while (scales < options.ballScales && smallest * std::pow(2.0, scales) <= 0.5 * depth[v])
      ++scales;
    const std::vector<double> ball = edgePathDistances(graph, { v }, smallest * std::pow(2.0, scales - 1));
    for (int k = 0; k < scales; ++k)
    {
      const double radius = smallest * std::pow(2.0, k);
      double inside = 0.0;
      for (int u = 0; u < n; ++u)
        if (ball[u] <= radius)
          inside += area[u];
      const double share = inside / (kPi * radius * radius);
      if (share >= options.largestBallShare || !capsSurface(graph, ball, radius, isLandmark))
        continue;
      protrusions.push_back({ v, featureOf[root[v]], depth[v] / unit, share, radius / unit });
      for (int u = 0; u < n; ++u)
        if (ball[u] <= radius)
          taken[u] = 1;
      break;
    }
  }
  return {};
}

namespace
{

/// `checkBaseDomain()` of `domain`, or of it with its holes closed when it
/// has boundary loops (`closeBaseDomain()`, which checks the closed one).
Status checkAnyBaseDomain(const BaseDomain& domain, int features)
{
  if (static_cast<int>(domain.featureIds.size()) != features)
    return Status::error("L0 has " + std::to_string(domain.featureIds.size()) + " features, not " +
      std::to_string(features));
  BaseDomain closed;
  BaseDomainHoles holes;
  return closeBaseDomain(domain, closed, holes);
}

/// The checks both entries share: one landmark list per surface, each of
/// `features` entries that fit its surface.
Status checkCollection(const std::vector<const TriangleMesh*>& surfaces, const std::vector<LandmarkList>& landmarks,
  std::size_t features, const std::string& against)
{
  const int models = static_cast<int>(surfaces.size());
  if (landmarks.size() != surfaces.size())
    return Status::error("protrusion cones: " + std::to_string(landmarks.size()) + " landmark lists for " +
      std::to_string(models) + " surfaces");
  for (int m = 0; m < models; ++m)
  {
    if (!surfaces[m])
      return Status::error("protrusion cones: model " + std::to_string(m) + " has no surface");
    if (landmarks[m].size() != features)
      return Status::error("protrusion cones: model " + std::to_string(m) + " has " +
        std::to_string(landmarks[m].size()) + " features, " + against + " " + std::to_string(features));
    if (Status s = validateLandmarks(landmarks[m], surfaces[m]->vertexCount(), -1, true); !s.ok())
      return Status::error("protrusion cones: model " + std::to_string(m) + ": " + s.message());
  }
  return {};
}

/// The cones on `base`: the tip's base triangle from model `preferred`
/// when it has the tip, else (`preferred` < 0, or without the tip) the
/// base triangle most of the models with the tip put it in (the first
/// such model's on a tie; a model that cannot be traced over `base` has
/// no say).
Status addCones(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const BaseDomain& base, int preferred, BaseDomain& domain, const ProtrusionConeOptions& options,
  ProtrusionConeReport& out)
{
  const int models = static_cast<int>(surfaces.size());
  const std::size_t features = base.featureIds.size();

  // Surfaces with boundaries are traced closed, as every stage runs them
  // (OpenSurface.h): each hole of L0 and of the surfaces capped, the caps'
  // curves given. The open L0's triangles come first in the closed one, so
  // a patch below `openTriangles` is the open L0's triangle.
  BaseDomain closedBase;
  BaseDomainHoles holes;
  if (Status s = closeBaseDomain(base, closedBase, holes); !s.ok())
    return Status::error("protrusion cones: " + s.message());
  const int openTriangles = base.mesh.triangleCount();
  for (int m = 0; m < models; ++m)
  {
    std::vector<std::vector<int>> loops;
    if (Status s = boundaryLoops(*surfaces[m], loops); !s.ok())
      return Status::error("protrusion cones: model " + std::to_string(m) + ": " + s.message());
    if (loops.size() != holes.loops.size())
      return Status::error("protrusion cones: model " + std::to_string(m) + " has " + std::to_string(loops.size()) +
        " boundary loops, L0 " + std::to_string(holes.loops.size()));
  }

  // Per model, the tip nearest to each feature where it has exactly one.
  out.protrusions.assign(models, {});
  std::vector<std::map<int, int>> tipOf(models);
  std::map<int, int> modelsWith;
  for (int m = 0; m < models; ++m)
  {
    if (missingLandmarkCount(landmarks[m]) > 0)
      continue;
    if (Status s = findProtrusions(*surfaces[m], landmarks[m], out.protrusions[m], options); !s.ok())
      return Status::error("model " + std::to_string(m) + ": " + s.message());
    std::map<int, int> count;
    for (const Protrusion& p : out.protrusions[m])
      ++count[p.nearestFeature];
    // A protrusion nearest to a boundary landmark leaves the body where the
    // surface was cut, not at a feature of it: no cone. Cut round the top
    // of the head, each ear is nearest to a boundary landmark, another on
    // each model, and 4 cones found on 2 or 3 models each left none with
    // every feature (the ears by one head landmark of a whole animal get
    // none either: two protrusions by one root).
    for (const Protrusion& p : out.protrusions[m])
      if (count[p.nearestFeature] == 1 && !holes.onBoundary(p.nearestFeature))
      {
        tipOf[m][p.nearestFeature] = p.vertex;
        ++modelsWith[p.nearestFeature];
      }
  }

  // The base triangle whose patch holds `model`'s tip of `root` (-1 if the
  // model cannot be traced over `base`, with the reason in `untraced`).
  std::map<int, TracedNet> nets;
  std::map<int, std::string> untraced;
  const auto tipTriangle = [&](int model, int root) {
    if (untraced.count(model))
      return -1;
    if (!nets.count(model))
    {
      const Status s = traceSurfaceWithBoundaries(*surfaces[model], landmarks[model], holes, closedBase, nets[model]);
      if (!s.ok())
      {
        nets.erase(model);
        untraced[model] = s.message();
        return -1;
      }
    }
    const TracedNet& net = nets[model];
    const int tip = tipOf[model][root];
    int triangle = -1;
    for (int t = 0; t < net.mesh.triangleCount(); ++t)
    {
      const Triangle& tri = net.mesh.triangle(t);
      const int patch = net.patchOfTriangle[t];
      if (std::find(tri.begin(), tri.end(), tip) != tri.end() && patch < openTriangles &&
        (triangle < 0 || patch < triangle))
        triangle = patch;
    }
    return triangle; // -1 not expected: a tip is never on a boundary, so never in a cap
  };

  struct Cone
  {
    int root, model, triangle, count;
  };
  std::vector<Cone> cones;
  for (const auto& [root, count] : modelsWith)
  {
    if (count < options.leastModels)
      continue;
    // Who chooses: the L0 model when it has the tip, else the models that
    // have it; over a built L0 the first of them that traces decides.
    std::vector<int> voters;
    for (int m = 0; m < models; ++m)
      if (tipOf[m].count(root))
        voters.push_back(m);
    if (preferred >= 0 && tipOf[preferred].count(root))
      voters = { preferred };
    std::map<int, int> votes;  // base triangle -> models
    std::map<int, int> firstOf; // base triangle -> the first model in it
    for (int m : voters)
    {
      const int triangle = tipTriangle(m, root);
      if (triangle < 0)
        continue;
      ++votes[triangle];
      firstOf.emplace(triangle, m);
      if (preferred >= 0)
        break;
    }
    int best = -1;
    for (const auto& [triangle, n] : votes)
      if (best < 0 || n > votes[best] || (n == votes[best] && firstOf[triangle] < firstOf[best]))
        best = triangle;
    if (best < 0)
    {
      // A built L0 fits its models: one that cannot be traced over it fails.
      for (int m : voters)
        if (preferred >= 0 && untraced.count(m))
          return Status::error("protrusion cones: model " + std::to_string(m) + ": " + untraced[m]);
      continue; // no model with the tip fits the given L0: no cone
    }
    cones.push_back({ root, firstOf[best], best, count });
  }
  // Only where every model with the protrusion agrees where it leaves the
  // body: its tip in the split triangle or one that shares an edge with
  // it. Otherwise the map would have to turn that model's protrusion round
  // the root across two curves or more: the CGAL bull's raised tail, with
  // the triceratops' and the camel's hanging, did not settle (1,900 times
  // isometric after 100 steps, 129 corner folds), and with the cone placed
  // on the bull instead it kept 15 folds against 6 without a cone.
  const auto sharesEdge = [&](int s, int t) {
    int shared = 0;
    for (int u : base.mesh.triangles[s])
      shared += std::count(base.mesh.triangles[t].begin(), base.mesh.triangles[t].end(), u) > 0 ? 1 : 0;
    return shared >= 2;
  };
  // Where the chosen triangle leaves a model apart, another may have every
  // tip in it or beside it (two models' tips in triangles that share only
  // the root, with one between them): the one that holds the most tips.
  std::vector<Cone> agreed;
  for (Cone c : cones)
  {
    std::vector<std::pair<int, int>> tips; // model, its tip's base triangle
    for (int m = 0; m < models; ++m)
      if (tipOf[m].count(c.root))
        if (const int triangle = tipTriangle(m, c.root); triangle >= 0)
          tips.emplace_back(m, triangle);
    // The first tip neither in `t` nor beside it (-1: none).
    const auto apartFrom = [&](int t) {
      for (std::size_t i = 0; i < tips.size(); ++i)
        if (!sharesEdge(tips[i].second, t))
          return static_cast<int>(i);
      return -1;
    };
    const int apart = apartFrom(c.triangle);
    if (apart >= 0)
    {
      int best = -1, bestInside = -1;
      for (int t = 0; t < base.mesh.triangleCount(); ++t)
      {
        if (apartFrom(t) >= 0)
          continue;
        const int inside = static_cast<int>(std::count_if(
          tips.begin(), tips.end(), [&](const std::pair<int, int>& tip) { return tip.second == t; }));
        if (inside > bestInside)
        {
          best = t;
          bestInside = inside;
        }
      }
      if (best < 0)
      {
        out.disagreeing.push_back({ c.root, tips[apart].first, tips[apart].second, c.triangle });
        continue;
      }
      c.triangle = best;
      c.model = tips.front().first;
      for (const auto& [m, triangle] : tips)
        if (triangle == best)
        {
          c.model = m;
          break;
        }
    }
    agreed.push_back(c);
  }
  cones = std::move(agreed);
  // One cone per base triangle: the one more models have.
  std::sort(cones.begin(), cones.end(), [](const Cone& a, const Cone& b) {
    return a.count != b.count ? a.count > b.count : a.root < b.root;
  });
  // And only while some model has every cone kept (it has every feature,
  // so the Missing Landmark Placer can build its reduced L0 from it): two
  // cones on two sets of models apart would leave the whole collection
  // unplaced.
  std::vector<Cone> kept;
  std::vector<char> complete(models, 0); // has every feature and every cone kept so far
  for (int m = 0; m < models; ++m)
    complete[m] = missingLandmarkCount(landmarks[m]) == 0;
  for (const Cone& c : cones)
  {
    if (std::any_of(kept.begin(), kept.end(), [&](const Cone& k) { return k.triangle == c.triangle; }))
      continue;
    bool someone = false;
    for (int m = 0; m < models; ++m)
      someone = someone || (complete[m] && tipOf[m].count(c.root));
    if (!someone)
      continue;
    for (int m = 0; m < models; ++m)
      complete[m] = complete[m] && tipOf[m].count(c.root);
    kept.push_back(c);
  }
  std::sort(kept.begin(), kept.end(), [](const Cone& a, const Cone& b) { return a.root < b.root; });

  domain = base;
  for (const Cone& c : kept)
  {
    const int vertex = domain.mesh.vertexCount();
    domain.mesh.points.push_back(surfaces[c.model]->points[tipOf[c.model][c.root]]);
    domain.featureIds.push_back(static_cast<int>(features + out.roots.size()));
    out.roots.push_back(c.root);
    out.tipModels.push_back(c.model);
    out.splitTriangles.push_back(c.triangle);
    const Triangle tri = base.mesh.triangles[c.triangle];
    for (int k = 0; k < 3; ++k)
      domain.mesh.triangles.push_back({ tri[k], tri[(k + 1) % 3], vertex });
  }
  // The split triangles go (in the order of the others, the new ones last).
  std::vector<Triangle> triangles;
  for (int t = 0; t < base.mesh.triangleCount(); ++t)
    if (std::none_of(kept.begin(), kept.end(), [&](const Cone& k) { return k.triangle == t; }))
      triangles.push_back(base.mesh.triangles[t]);
  triangles.insert(triangles.end(), domain.mesh.triangles.begin() + base.mesh.triangleCount(),
    domain.mesh.triangles.end());
  domain.mesh.triangles = std::move(triangles);
  if (Status s = checkAnyBaseDomain(domain, static_cast<int>(features + kept.size())); !s.ok())
    return Status::error("protrusion cones: internal error: " + s.message());

  for (int m = 0; m < models; ++m)
    for (const Cone& c : kept)
    {
      const auto found = tipOf[m].find(c.root);
      landmarks[m].push_back(found != tipOf[m].end() ? found->second : kMissingLandmark);
    }
  return {};
}

} // namespace

Status addProtrusionCones(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  int baseDomainModel, BaseDomain& domain, const ProtrusionConeOptions& options, ProtrusionConeReport* report)
{
  ProtrusionConeReport local;
  ProtrusionConeReport& out = report ? *report : local;
  out = ProtrusionConeReport{};
  if (Status s = checkOptions(options); !s.ok())
    return s;
  const int models = static_cast<int>(surfaces.size());
  if (landmarks.size() != surfaces.size())
    return checkCollection(surfaces, landmarks, 0, ""); // says so
  if (baseDomainModel < 0 || baseDomainModel >= models)
    return Status::error("protrusion cones: there is no model " + std::to_string(baseDomainModel));
  const std::size_t features = landmarks[baseDomainModel].size();
  if (Status s = checkCollection(surfaces, landmarks, features, "model " + std::to_string(baseDomainModel)); !s.ok())
    return s;
  if (missingLandmarkCount(landmarks[baseDomainModel]) > 0)
    return Status::error("protrusion cones: model " + std::to_string(baseDomainModel) +
      ", which L0 is built from, misses landmarks");

  BaseDomain built;
  if (Status s = buildBaseDomain(*surfaces[baseDomainModel], landmarks[baseDomainModel], built); !s.ok())
    return s;
  return addCones(surfaces, landmarks, built, baseDomainModel, domain, options, out);
}

Status addProtrusionCones(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const BaseDomain& given, BaseDomain& domain, const ProtrusionConeOptions& options, ProtrusionConeReport* report)
{
  ProtrusionConeReport local;
  ProtrusionConeReport& out = report ? *report : local;
  out = ProtrusionConeReport{};
  if (Status s = checkOptions(options); !s.ok())
    return s;
  const std::size_t features = given.featureIds.size();
  if (Status s = checkAnyBaseDomain(given, static_cast<int>(features)); !s.ok())
    return Status::error("protrusion cones: the given L0: " + s.message());
  if (Status s = checkCollection(surfaces, landmarks, features, "the given L0"); !s.ok())
    return s;
  return addCones(surfaces, landmarks, given, -1, domain, options, out);
}

} // namespace cmp
