#include <cmp/numerics/Threads.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace cmp
{

void forEachOnThreads(int count, int threads, const std::function<void(int)>& task,
  const std::function<void(int, const char*)>& failed, const std::function<void(int)>& progress)
{
  const int threadCount = std::clamp(threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()),
    1, std::max(1, count));
  std::atomic<int> next{ 0 };
  std::atomic<int> done{ 0 };
  int reported = 0; // tasks done when the calling thread last reported
  const auto work = [&](bool callingThread) {
    for (int i = next++; i < count; i = next++)
    {
      try
      {
        task(i);
      }
      catch (const std::exception& error)
      {
        failed(i, error.what());
      }
      const int finished = ++done;
      if (callingThread && progress && finished > reported)
      {
        reported = finished;
        progress(finished);
      }
    }
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threadCount; ++t)
    helpers.emplace_back(work, false);
  work(true);
  for (std::thread& helper : helpers)
    helper.join();
}

} // namespace cmp
