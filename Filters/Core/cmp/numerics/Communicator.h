#pragma once
/// \file Communicator.h
/// \brief The few collective operations the collection algorithms need to
///        combine models spread over several processes, and the serial
///        implementation.

#include <cmp/mesh/Status.h>

#include <cstddef>
#include <vector>

namespace cmp
{

/// \brief Combines values across the processes that together hold one
///        collection of models.
///
/// The core stays free of MPI: the VTK layer implements this interface with
/// `vtkMultiProcessController`, the tests with threads. Every operation is
/// collective: all ranks call it in the same order with the same `count`
/// and `root`. Implementations must give every rank bitwise the same result
/// (sum in a fixed order), because the callers take decisions, such as how
/// many modes to keep, from these results on every rank independently.
class Communicator
{
public:
  virtual ~Communicator() = default;

  /// \brief This process's rank, 0 .. size() - 1.
  virtual int rank() const = 0;
  /// \brief Number of processes.
  virtual int size() const = 0;
  /// \brief Replaces `values[0 .. count)` on every rank by their element-wise
  ///        sum over all ranks.
  virtual void allReduceSum(double* values, std::size_t count) = 0;
  /// \brief Copies `values[0 .. count)` of rank `root` to every other rank.
  virtual void broadcast(double* values, std::size_t count, int root) = 0;
  /// \brief Every rank's `value`, indexed by rank.
  virtual std::vector<int> allGather(int value) = 0;
};

/// \brief The communicator of a process that holds the whole collection.
class SingleProcess final : public Communicator
{
public:
  /// \brief Always 0.
  int rank() const override { return 0; }
  /// \brief Always 1.
  int size() const override { return 1; }
  /// \brief Leaves `values` as they are: the sum over one rank.
  void allReduceSum(double*, std::size_t) override {}
  /// \brief Leaves `values` as they are: the root is this process.
  void broadcast(double*, std::size_t, int) override {}
  /// \brief `{ value }`.
  std::vector<int> allGather(int value) override { return { value }; }
};

/// \brief Makes a check that each rank did on its own part collective: if
///        any rank's `local` status is an error, every rank returns the
///        error of the lowest such rank (its message sent to all), so that
///        all ranks stop together instead of some waiting forever in the
///        next collective operation. Collective.
Status agreeOnStatus(const Status& local, Communicator& communicator);

} // namespace cmp
