// Times the collection algorithms at the size the issue asks for: 100
// models of 40,000 vertices, aligned to equal volume, then 10 principal
// components. Not a test (timings depend on the machine); run by hand:
//
//   <build>/bin/cmp_shape_analysis_timing [models] [modes]

#include "MeshPCA.h"
#include "ProcrustesAlignment.h"
#include "TestMeshes.h"
#include "TestShapes.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>

using namespace cmp;

namespace
{

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char** argv)
{
  const int modelCount = argc > 1 ? std::atoi(argv[1]) : 100;
  const int modeCount = argc > 2 ? std::atoi(argv[2]) : 10;
  const TriangleMesh torus = test::torus(200, 200); // 40,000 vertices

  std::vector<std::vector<Vec3>> fields;
  for (unsigned j = 0; j < 12; ++j)
    fields.push_back(test::smoothField(torus.points, 0.2 / (1.0 + j), j));
  std::mt19937 random(1);
  ShapeList models;
  for (const std::vector<Vec3>& model : test::deformedCopies(torus.points, fields, modelCount, 100))
    models.push_back(test::moved(model, test::randomSimilarity(random, 5.0, 0.5, 2.0)));

  const auto start = std::chrono::steady_clock::now();
  ShapeAlignment alignment;
  Status status = alignShapes(models, torus.triangles, AlignmentOptions(), alignment);
  const double alignSeconds = secondsSince(start);
  MeshPCA pca;
  if (status.ok())
    status = computeMeshPCA(alignment.alignedModels, modeCount, pca);
  const double totalSeconds = secondsSince(start);
  if (!status.ok())
  {
    std::fprintf(stderr, "%s\n", status.message().c_str());
    return 1;
  }
  std::printf("%d models x %d vertices: alignment %.3f s (%d iterations), PCA (%d modes) %.3f s, total %.3f s\n",
    modelCount, torus.vertexCount(), alignSeconds, alignment.iterations, pca.modeCount(),
    totalSeconds - alignSeconds, totalSeconds);
  std::printf("explained variance of the modes:");
  for (Eigen::Index k = 0; k < pca.explainedVarianceRatios.size(); ++k)
    std::printf(" %.3g", pca.explainedVarianceRatios(k));
  std::printf("\n");
  return 0;
}
