// The background job's handshake: supersession, cancel, interrupt, progress, ordering and a
// destructor that joins a running work. No assertion about durations: sleeps only make overlap
// likely, and every wait is a poll loop that ctest's timeout would end if it never returned.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "base/background_job.h"

using namespace gridifs;

namespace {

using IntJob = BackgroundJob<int, int>;

void nap() { std::this_thread::sleep_for(std::chrono::milliseconds(1)); }

template <class Predicate>
void waitFor(Predicate predicate) {
  while (!predicate()) nap();
}

/// Polls until the job is idle and returns every result seen, in the order seen.
std::vector<IntJob::Result> drain(IntJob& job) {
  std::vector<IntJob::Result> seen;
  for (;;) {
    const bool idle = !job.busy();
    while (auto r = job.poll()) seen.push_back(*r);
    if (idle) break;
    nap();
  }
  return seen;
}

}  // namespace

TEST(BackgroundJob, PublishesTheResultTaggedWithItsGeneration) {
  IntJob job([](const int& x, IntJob::Context& ctx) { ctx.publish(x * 2); });
  EXPECT_FALSE(job.poll());
  const std::uint64_t g = job.submit(21);
  EXPECT_EQ(g, 1u);
  const auto seen = drain(job);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].generation, 1u);
  EXPECT_EQ(seen[0].value, 42);
  EXPECT_FALSE(job.poll());  // once
}

TEST(BackgroundJob, ANewInputSupersedesARunningOne) {
  std::atomic<bool> firstStarted{false}, stalePublishAccepted{true};
  IntJob job([&](const int& x, IntJob::Context& ctx) {
    if (x == 1) {
      firstStarted = true;
      waitFor([&] { return ctx.stale(); });   // runs until superseded
      stalePublishAccepted = ctx.publish(1);  // too late: must be dropped
      return;
    }
    ctx.publish(x);
  });
  job.submit(1);
  waitFor([&] { return firstStarted.load(); });
  const std::uint64_t second = job.submit(2);
  const auto seen = drain(job);
  EXPECT_FALSE(stalePublishAccepted.load());
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].generation, second);
  EXPECT_EQ(seen[0].value, 2);
}

TEST(BackgroundJob, AStaleRunNeverPublishesAfterTheNewOne) {
  // The old run keeps publishing after it is superseded (it ignores stale()); the new run
  // publishes once. Nothing of the old generation may follow the new one.
  std::atomic<bool> firstStarted{false}, secondDone{false};
  IntJob job([&](const int& x, IntJob::Context& ctx) {
    if (x == 1) {
      firstStarted = true;
      for (int i = 0; i < 200 && !secondDone; ++i) {
        ctx.publish(1);
        nap();
      }
      return;
    }
    ctx.publish(2);
    secondDone = true;
  });
  job.submit(1);
  waitFor([&] { return firstStarted.load(); });
  job.submit(2);
  std::vector<IntJob::Result> seen;
  // One worker thread: the second input runs after the first returns.
  waitFor([&] {
    while (auto r = job.poll()) seen.push_back(*r);
    return secondDone.load() && !job.busy();
  });
  while (auto r = job.poll()) seen.push_back(*r);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back().value, 2);
  bool sawNew = false;
  for (const auto& r : seen) {
    if (r.generation == 2) sawNew = true;
    if (sawNew) {
      EXPECT_EQ(r.generation, 2u);
      EXPECT_EQ(r.value, 2);
    }
  }
}

TEST(BackgroundJob, ResultsArriveInGenerationOrder) {
  IntJob job([](const int& x, IntJob::Context& ctx) {
    for (int i = 0; i < 3 && !ctx.stale(); ++i) {
      ctx.publish(x);
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  std::vector<IntJob::Result> seen;
  std::uint64_t last = 0;
  for (int i = 1; i <= 50; ++i) {
    last = job.submit(i);
    if (i % 3 == 0) nap();
    while (auto r = job.poll()) seen.push_back(*r);
  }
  const auto rest = drain(job);
  seen.insert(seen.end(), rest.begin(), rest.end());
  ASSERT_FALSE(seen.empty());
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i - 1].generation, seen[i].generation);
  for (const auto& r : seen) EXPECT_EQ(std::uint64_t(r.value), r.generation);  // input i is generation i
  EXPECT_EQ(seen.back().generation, last);
}

TEST(BackgroundJob, CancelStopsTheRunAndDropsItsResult) {
  std::atomic<bool> started{false}, sawStale{false}, accepted{true};
  IntJob job([&](const int&, IntJob::Context& ctx) {
    started = true;
    waitFor([&] { return ctx.stale(); });
    sawStale = ctx.stopRequested() && *ctx.stopFlag();
    accepted = ctx.publish(7);
  });
  job.submit(1);
  waitFor([&] { return started.load(); });
  job.cancel();
  EXPECT_FALSE(job.busy());
  EXPECT_EQ(job.progress().fraction, 0.0);
  waitFor([&] { return sawStale.load(); });
  const auto seen = drain(job);
  EXPECT_TRUE(seen.empty());
  EXPECT_FALSE(accepted.load());
}

TEST(BackgroundJob, CancelDropsAnInputNotYetStarted) {
  std::atomic<bool> release{false};
  std::atomic<int> runs{0};
  IntJob job([&](const int& x, IntJob::Context& ctx) {
    ++runs;
    (void)ctx;
    if (x == 1) waitFor([&] { return release.load(); });  // ignores stale(): input 2 must wait
  });
  job.submit(1);
  waitFor([&] { return runs.load() == 1; });
  job.submit(2);  // waits behind the first
  job.cancel();   // drops both
  release = true;
  drain(job);
  job.submit(3);
  drain(job);
  EXPECT_EQ(runs.load(), 2);  // inputs 1 and 3
}

TEST(BackgroundJob, InterruptStopsEarlyAndKeepsTheOutcome) {
  std::atomic<bool> started{false};
  IntJob job([&](const int&, IntJob::Context& ctx) {
    started = true;
    while (!ctx.stopRequested()) nap();
    EXPECT_FALSE(ctx.stale());
    ctx.publish(-1);  // "cancelled after some steps": still delivered
  });
  const std::uint64_t g = job.submit(1);
  waitFor([&] { return started.load(); });
  EXPECT_FALSE(job.interrupted());
  job.interrupt();
  EXPECT_TRUE(job.interrupted());
  const auto seen = drain(job);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].generation, g);
  EXPECT_EQ(seen[0].value, -1);
}

TEST(BackgroundJob, ReportsTheNewestRunsProgress) {
  std::atomic<bool> reported{false}, release{false};
  IntJob job([&](const int& x, IntJob::Context& ctx) {
    if (x == 1) {
      ctx.progress(0.25);
    } else {
      ctx.progress(30, 120);
    }
    reported = true;
    waitFor([&] { return release.load() || ctx.stale(); });
    if (x == 1) ctx.progress(0.9);  // a stale run's progress never shows as the new one's
  });
  EXPECT_EQ(job.progress().fraction, 0.0);
  job.submit(1);
  waitFor([&] { return reported.load(); });
  EXPECT_EQ(job.progress().fraction, 0.25);
  reported = false;
  job.submit(2);
  EXPECT_EQ(job.progress().fraction, 0.0);  // not started yet, or started and reset
  waitFor([&] { return reported.load(); });
  const JobProgress p = job.progress();
  EXPECT_EQ(p.done, 30);
  EXPECT_EQ(p.total, 120);
  EXPECT_EQ(p.fraction, 0.25);
  release = true;
  drain(job);
}

TEST(BackgroundJob, DestructionWhileRunningJoins) {
  // The work never ends on its own: only the destructor's stale flag stops it, so this test
  // finishes only if the destructor marks the run stale and joins.
  std::atomic<bool> started{false}, finished{false};
  auto job = std::make_unique<IntJob>([&](const int&, IntJob::Context& ctx) {
    started = true;
    while (!ctx.stale()) nap();
    finished = true;
  });
  job->submit(1);
  job->submit(2);  // pending behind the first: dropped by the destructor, never run
  waitFor([&] { return started.load(); });
  job.reset();
  EXPECT_TRUE(finished.load());
}

TEST(BackgroundJob, DestructionWhileIdleJoins) {
  IntJob job([](const int&, IntJob::Context&) {});
  EXPECT_FALSE(job.busy());
}

TEST(BackgroundJob, InputsStayImmutableAndMoveOnlyOutputsWork) {
  using Job = BackgroundJob<std::shared_ptr<const std::vector<int>>, std::unique_ptr<int>>;
  Job job([](const std::shared_ptr<const std::vector<int>>& v, Job::Context& ctx) {
    int sum = 0;
    for (int x : *v) sum += x;
    ctx.publish(std::make_unique<int>(sum));
  });
  job.submit(std::make_shared<const std::vector<int>>(std::vector<int>{1, 2, 3}));
  std::optional<Job::Result> r;
  waitFor([&] { return (r = job.poll()).has_value(); });
  ASSERT_TRUE(r->value);
  EXPECT_EQ(*r->value, 6);
}
