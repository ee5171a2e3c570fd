#pragma once
/// \file ThreadCommunicator.h
/// \brief A communicator whose ranks are threads of the test process, so
///        that the core's distributed code paths run and are compared with
///        one process without MPI.

#include <cmp/numerics/Communicator.h>

#include <functional>

namespace cmp::test
{

/// \brief Runs `work` once per rank on `rankCount` threads, each given its
///        own communicator, and returns when all have finished.
///
/// The ranks combine like MPI processes: sums are taken in rank order, so
/// every rank receives bitwise the same result. A collective operation
/// that the ranks do not all call alike (another operation, count or root)
/// is reported as a test failure; one that some rank never reaches aborts
/// the test program after a minute rather than hanging it.
void runOnRanks(int rankCount, const std::function<void(Communicator&)>& work);

} // namespace cmp::test
