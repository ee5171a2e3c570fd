#pragma once
/// \file DetailTransfer.h
/// \brief Scale-dependent blending of two consistently remeshed models in
///        the wavelet domain: the coarse shape of one with the details of
///        the other (the paper's Figure 13, cow onto horse), or any
///        per-level mix of the two.

#include <cmp/analysis/LoopWavelet.h>
#include <cmp/mesh/Status.h>

#include <Eigen/Core>

#include <vector>

namespace cmp
{

/// \brief Weight of model B per level, J + 1 entries: entry 0 for the
///        coarsest values, entry l (1..J) for the details of level l.
///        0 keeps A's coefficients, 1 takes B's, values between blend
///        linearly and values outside [0, 1] extrapolate.
using DetailSchedule = std::vector<double>;

/// \brief The paper's Figure 13 with a threshold: A's coarsest values and
///        A's details up to level `lastLevelOfA`, B's details above it.
///        `lastLevelOfA` = 0 puts all of B's details on A's coarsest mesh.
DetailSchedule detailsOfBAbove(int finestLevel, int lastLevelOfA);

/// \brief Whether details keep their size or follow the size of the
///        coarse shape they are put on.
enum class DetailScaling
{
  Absolute, ///< Details keep their length.
  /// \brief Each model's details are scaled by size(C) / size(model),
  ///        where C is the blended coarsest level and size is the RMS
  ///        distance of the coarsest values from their mean: details put
  ///        on a coarse shape half as large arrive at half their length.
  RelativeToCoarseSize
};

/// \brief Blends two coefficient sets level by level: with w = `weightOfB`,
///        the coarsest level is C = (1 - w_0) A + w_0 B and the details of
///        level l are (1 - w_l) s_A A + w_l s_B B, where s_A = s_B = 1 for
///        `DetailScaling::Absolute`, else size(C) / size(A) and
///        size(C) / size(B).
///
/// Both sets must come from the same transform (same levels and vertices),
/// have the same number of columns and the same detail frame; local frames
/// (`DetailFrame::Local`) are the right choice for positions, since the
/// details then sit on whichever coarse shape they are synthesized on.
/// Either way, all weights 0 give A and all weights 1 give B exactly.
/// `out` may be `a` or `b`. Paper §3 ("Transfer of Wavelet Details",
/// Figure 13, and its scheduled morphs); the size scaling is ours.
///
/// Fails (Status), leaving `out` untouched, when the two sets differ in
/// levels, vertices, columns or frame, are empty or not one row per finest
/// vertex, hold a non-finite value, the schedule has not J + 1 finite
/// weights, or (`RelativeToCoarseSize`) a model's coarsest values are all
/// equal.
Status transferDetails(const WaveletCoefficients& a, const WaveletCoefficients& b, const DetailSchedule& weightOfB,
  WaveletCoefficients& out, DetailScaling scaling = DetailScaling::RelativeToCoarseSize);

/// \brief The whole transfer on values (V_J rows each): analyzes `a` and
///        `b` with `frame`, blends with `weightOfB` and synthesizes.
/// Fails (Status) where `analyze()` fails ("model A: ...", "model B: ...":
/// a transform not built, values of the wrong size or not finite), where
/// the blend above fails, or where `synthesize()` fails.
Status transferDetails(const LoopWaveletTransform& transform, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
  const DetailSchedule& weightOfB, Eigen::MatrixXd& out, DetailFrame frame = DetailFrame::Local,
  DetailScaling scaling = DetailScaling::RelativeToCoarseSize);

} // namespace cmp
