#include <cmp/numerics/Communicator.h>

#include <algorithm>
#include <string>

namespace cmp
{

Status agreeOnStatus(const Status& local, Communicator& communicator)
{
  const std::vector<int> failed = communicator.allGather(local.ok() ? 0 : 1);
  const auto first = std::find(failed.begin(), failed.end(), 1);
  if (first == failed.end())
    return Status();
  const int root = static_cast<int>(first - failed.begin());

  // The interface only moves doubles; a message is short, so one double per
  // character costs nothing and keeps the interface minimal.
  double length = communicator.rank() == root ? static_cast<double>(local.message().size()) : 0.0;
  communicator.broadcast(&length, 1, root);
  std::vector<double> characters(static_cast<std::size_t>(length));
  if (communicator.rank() == root)
    std::copy(local.message().begin(), local.message().end(), characters.begin());
  communicator.broadcast(characters.data(), characters.size(), root);

  std::string message(characters.size(), ' ');
  std::transform(characters.begin(), characters.end(), message.begin(),
    [](double c) { return static_cast<char>(static_cast<int>(c)); });
  return Status::error(message);
}

} // namespace cmp
