#include "BenchmarkShapeAnalysis.h"

#include <cmp/analysis/MeshPCA.h>
#include <cmp/analysis/ProcrustesAlignment.h>
#include "TestShapes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <random>

namespace cmp::bench
{

Status timeShapeAnalysis(int models, int side, int modes, int repetitions, ShapeAnalysisTiming& out)
{
  using Clock = std::chrono::steady_clock;
  const TriangleMesh torus = test::torus(side, side);
  // Twelve smooth fields, weaker with their index: a spectrum with a few
  // dominant modes, as real collections have.
  std::vector<std::vector<Vec3>> fields;
  for (unsigned j = 0; j < 12; ++j)
    fields.push_back(test::smoothField(torus.points, 0.2 / (1.0 + j), j));
  std::mt19937 random(1);
  ShapeList collection;
  for (const std::vector<Vec3>& model : test::deformedCopies(torus.points, fields, models, 100))
    collection.push_back(test::moved(model, test::randomSimilarity(random, 5.0, 0.5, 2.0)));

  out = ShapeAnalysisTiming{ models, torus.vertexCount(), 0, 0, std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity(), 0.0, 0 };
  for (int run = 0; run < std::max(1, repetitions); ++run)
  {
    const Clock::time_point start = Clock::now();
    ShapeAlignment alignment;
    if (Status s = alignShapes(collection, torus.triangles, AlignmentOptions(), alignment); !s.ok())
      return Status::error("alignment: " + s.message());
    const Clock::time_point aligned = Clock::now();
    MeshPCA pca;
    if (Status s = computeMeshPCA(alignment.alignedModels, modes, pca); !s.ok())
      return Status::error("PCA: " + s.message());
    const Clock::time_point done = Clock::now();
    out.alignSeconds = std::min(out.alignSeconds, std::chrono::duration<double>(aligned - start).count());
    out.pcaSeconds = std::min(out.pcaSeconds, std::chrono::duration<double>(done - aligned).count());
    out.iterations = alignment.iterations;
    out.modes = pca.modeCount();
    out.firstRatio = pca.explainedVarianceRatios.size() > 0 ? pca.explainedVarianceRatios(0) : 0.0;
    ++out.runs;
  }
  return {};
}

std::string describe(const ShapeAnalysisTiming& t)
{
  char text[512];
  std::snprintf(text, sizeof text,
    "shape analysis (`pca`): %d models x %d vertices (smoothly deformed, moved and scaled copies of a torus grid): "
    "alignment to equal volume %.3f s (%d iterations) + %d principal components %.3f s = **%.3f s** (target < 2 s); "
    "mode 0 explains %.1f%% of the variance; best of %d runs",
    t.models, t.vertices, t.alignSeconds, t.iterations, t.modes, t.pcaSeconds, t.alignSeconds + t.pcaSeconds,
    100.0 * t.firstRatio, t.runs);
  return text;
}

} // namespace cmp::bench
