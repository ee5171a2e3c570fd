#include <cmp/numerics/Communicator.h>
#include "ThreadCommunicator.h"

#include <gtest/gtest.h>

#include <mutex>
#include <string>

using namespace cmp;

TEST(Communicator, EveryRankGetsTheErrorOfTheLowestFailingRank)
{
  std::mutex mutex;
  test::runOnRanks(4, [&](Communicator& communicator) {
    const int rank = communicator.rank();
    const Status local = rank == 1 || rank == 3 ? Status::error("rank " + std::to_string(rank) + " failed: \xc3\xa9")
                                                 : Status();
    const Status agreed = agreeOnStatus(local, communicator);
    const Status fine = agreeOnStatus(Status(), communicator);
    const std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(agreed.message(), "rank 1 failed: \xc3\xa9") << "rank " << rank;
    EXPECT_TRUE(fine.ok());
  });
}

TEST(Communicator, ThreadRanksCombineLikeProcesses)
{
  std::mutex mutex;
  test::runOnRanks(3, [&](Communicator& communicator) {
    const int rank = communicator.rank();
    double values[2] = { 1.0 + rank, 10.0 * rank };
    communicator.allReduceSum(values, 2);
    double broadcast[2] = { static_cast<double>(rank), -1.0 * rank };
    communicator.broadcast(broadcast, 2, 2);
    const std::vector<int> gathered = communicator.allGather(7 * rank);
    const std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(communicator.size(), 3);
    EXPECT_EQ(values[0], 6.0);
    EXPECT_EQ(values[1], 30.0);
    EXPECT_EQ(broadcast[0], 2.0);
    EXPECT_EQ(broadcast[1], -2.0);
    EXPECT_EQ(gathered, std::vector<int>({ 0, 7, 14 }));
  });

  SingleProcess serial;
  double value = 4.0;
  serial.allReduceSum(&value, 1);
  serial.broadcast(&value, 1, 0);
  EXPECT_EQ(value, 4.0);
  EXPECT_EQ(serial.allGather(3), std::vector<int>({ 3 }));
  EXPECT_TRUE(agreeOnStatus(Status(), serial).ok());
  EXPECT_EQ(agreeOnStatus(Status::error("bad"), serial).message(), "bad");
}
