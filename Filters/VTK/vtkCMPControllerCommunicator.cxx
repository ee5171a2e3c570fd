#include "vtkCMPControllerCommunicator.h"

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

#include <algorithm>
#include <vector>

namespace cmp::bridge
{

namespace
{

/// VTK's collectives count in vtkIdType; large sums go in chunks.
constexpr std::size_t kChunk = static_cast<std::size_t>(1) << 28;

} // namespace

ControllerCommunicator::ControllerCommunicator(vtkMultiProcessController* controller)
  : controller_(controller ? controller : vtkMultiProcessController::GetGlobalController())
{
  if (controller_ && controller_->GetNumberOfProcesses() <= 1)
    controller_ = nullptr;
}

int ControllerCommunicator::rank() const
{
  return controller_ ? controller_->GetLocalProcessId() : 0;
}

int ControllerCommunicator::size() const
{
  return controller_ ? controller_->GetNumberOfProcesses() : 1;
}

void ControllerCommunicator::allReduceSum(double* values, std::size_t count)
{
  if (!controller_)
    return;
  std::vector<double> sum;
  for (std::size_t start = 0; start < count; start += kChunk)
  {
    const std::size_t n = std::min(kChunk, count - start);
    sum.resize(n);
    controller_->Reduce(values + start, sum.data(), static_cast<vtkIdType>(n), vtkCommunicator::SUM_OP, 0);
    if (rank() == 0)
      std::copy(sum.begin(), sum.end(), values + start);
    controller_->Broadcast(values + start, static_cast<vtkIdType>(n), 0);
  }
}

void ControllerCommunicator::broadcast(double* values, std::size_t count, int root)
{
  if (!controller_)
    return;
  for (std::size_t start = 0; start < count; start += kChunk)
    controller_->Broadcast(values + start, static_cast<vtkIdType>(std::min(kChunk, count - start)), root);
}

std::vector<int> ControllerCommunicator::allGather(int value)
{
  std::vector<int> all(size(), value);
  if (controller_)
    controller_->AllGather(&value, all.data(), 1);
  return all;
}

} // namespace cmp::bridge
