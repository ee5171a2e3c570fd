#pragma once
/// \file vtkCMPControllerCommunicator.h
/// \brief The core's Communicator over VTK's vtkMultiProcessController, so
///        the collection algorithms combine models spread over the ranks of
///        `mpirun ... pvbatch` (private header, not wrapped).

#include <cmp/numerics/Communicator.h>

class vtkMultiProcessController;

namespace cmp::bridge
{

/// \brief Collective operations of the core on a vtkMultiProcessController
///        (the global one by default). Without a controller, or with one
///        process, it behaves as cmp::SingleProcess.
class ControllerCommunicator final : public Communicator
{
public:
  /// \brief Uses `controller`, or the global controller when null.
  explicit ControllerCommunicator(vtkMultiProcessController* controller = nullptr);

  /// \brief This process's rank.
  int rank() const override;
  /// \brief Number of processes.
  int size() const override;
  /// \brief Sum on rank 0, then broadcast: every rank gets bitwise the
  ///        same sum (an all-reduce need not promise that).
  void allReduceSum(double* values, std::size_t count) override;
  /// \brief Rank `root`'s values to every rank.
  void broadcast(double* values, std::size_t count, int root) override;
  /// \brief Every rank's value.
  std::vector<int> allGather(int value) override;

private:
  vtkMultiProcessController* controller_ = nullptr;
};

} // namespace cmp::bridge
