#pragma once
/// \file BenchmarkShapeAnalysis.h
/// \brief Times the collection algorithms of the paper's Section 3 at the
///        size the issue asks for: alignment and principal components of
///        100 models of 40,000 vertices.

#include <cmp/mesh/Status.h>

#include <string>

namespace cmp::bench
{

/// \brief What one timing of alignment plus PCA measured.
struct ShapeAnalysisTiming
{
  int models = 0;            ///< Models in the collection.
  int vertices = 0;          ///< Vertices per model.
  int modes = 0;             ///< Principal components computed.
  int iterations = 0;        ///< Alignment iterations until the mean was stable.
  double alignSeconds = 0.0; ///< Best time of generalised Procrustes alignment (equal volume).
  double pcaSeconds = 0.0;   ///< Best time of the PCA of the aligned models.
  double firstRatio = 0.0;   ///< Explained variance ratio of mode 0 (a sanity figure).
  int runs = 0;              ///< Runs; the best time counts.
};

/// \brief Aligns (to equal volume) and decomposes `models` smoothly
///        deformed, randomly moved and scaled copies of a torus of
///        `side` x `side` vertices, keeping `modes` modes, `repetitions`
///        times; the collection is built once, untimed.
Status timeShapeAnalysis(int models, int side, int modes, int repetitions, ShapeAnalysisTiming& out);

/// \brief One line for the report: sizes, times and the target.
std::string describe(const ShapeAnalysisTiming& timing);

} // namespace cmp::bench
