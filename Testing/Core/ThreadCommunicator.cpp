#include "ThreadCommunicator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>
#include <vector>

namespace cmp::test
{
namespace
{

/// What the ranks post for one collective operation, one slot per rank.
struct Post
{
  int operation = 0;
  std::size_t count = 0;
  int root = 0;
  double* values = nullptr;
  int integer = 0;
};

/// The state the ranks share: their posts and a reusable barrier.
class Rendezvous
{
public:
  explicit Rendezvous(int rankCount)
    : posts(static_cast<std::size_t>(rankCount))
    , rankCount_(rankCount)
  {
  }

  /// Returns when every rank has called it as often as this one.
  void wait()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    const long generation = generation_;
    if (++arrived_ == rankCount_)
    {
      arrived_ = 0;
      ++generation_;
      changed_.notify_all();
      return;
    }
    if (!changed_.wait_for(lock, std::chrono::minutes(1), [&] { return generation_ != generation; }))
    {
      std::fprintf(stderr, "ThreadCommunicator: a rank never reached a collective operation\n");
      std::abort();
    }
  }

  std::vector<Post> posts;

private:
  std::mutex mutex_;
  std::condition_variable changed_;
  const int rankCount_;
  int arrived_ = 0;
  long generation_ = 0;
};

enum Operation
{
  AllReduceSum = 1,
  Broadcast,
  AllGather
};

class ThreadRank final : public Communicator
{
public:
  ThreadRank(Rendezvous& rendezvous, int rank, int size)
    : rendezvous_(rendezvous)
    , rank_(rank)
    , size_(size)
  {
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void allReduceSum(double* values, std::size_t count) override
  {
    if (!post({ AllReduceSum, count, 0, values, 0 }))
      return;
    std::vector<double> sum(count, 0.0);
    for (const Post& other : rendezvous_.posts)
    {
      for (std::size_t i = 0; i < count; ++i)
        sum[i] += other.values[i];
    }
    // Nobody may overwrite its input before every rank has read it.
    rendezvous_.wait();
    std::copy(sum.begin(), sum.end(), values);
  }

  void broadcast(double* values, std::size_t count, int root) override
  {
    if (!post({ Broadcast, count, root, values, 0 }))
      return;
    if (rank_ != root)
      std::copy(rendezvous_.posts[root].values, rendezvous_.posts[root].values + count, values);
    rendezvous_.wait();
  }

  std::vector<int> allGather(int value) override
  {
    std::vector<int> values;
    if (!post({ AllGather, 0, 0, nullptr, value }))
      return std::vector<int>(static_cast<std::size_t>(size_), 0);
    for (const Post& other : rendezvous_.posts)
      values.push_back(other.integer);
    rendezvous_.wait();
    return values;
  }

private:
  /// Posts this rank's part and waits for the others'; false (and a test
  /// failure) when they did not call the same operation alike.
  bool post(const Post& mine)
  {
    rendezvous_.posts[rank_] = mine;
    rendezvous_.wait();
    const Post& first = rendezvous_.posts[0];
    bool alike = true;
    for (const Post& other : rendezvous_.posts)
      alike = alike && other.operation == first.operation && other.count == first.count && other.root == first.root;
    if (!alike)
    {
      ADD_FAILURE() << "rank " << rank_ << ": ranks called different collective operations";
      rendezvous_.wait();
    }
    return alike;
  }

  Rendezvous& rendezvous_;
  const int rank_;
  const int size_;
};

} // namespace

void runOnRanks(int rankCount, const std::function<void(Communicator&)>& work)
{
  Rendezvous rendezvous(rankCount);
  std::vector<std::thread> threads;
  for (int rank = 0; rank < rankCount; ++rank)
  {
    threads.emplace_back([&rendezvous, &work, rank, rankCount] {
      ThreadRank communicator(rendezvous, rank, rankCount);
      work(communicator);
    });
  }
  for (std::thread& thread : threads)
    thread.join();
}

} // namespace cmp::test
