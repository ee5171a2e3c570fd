#pragma once
/// \file Threads.h
/// \brief Independent tasks (models, patches) shared out over threads.

#include <functional>

namespace cmp
{

/// \brief Runs `task(i)` for every i in [0, `count`) on up to `threads`
///        threads (0: one per hardware thread), the calling thread among
///        them: each thread takes the next index not yet taken. After each
///        task the calling thread, and only it, calls `progress(done)`, if
///        set, with the number of tasks finished so far. Returns when every
///        task has run. A task that throws has its exception's message
///        passed to `failed(i, message)` (the task counts as done).
///
/// \pre `task` may run on any thread; tasks share nothing they write.
void forEachOnThreads(int count, int threads, const std::function<void(int)>& task,
  const std::function<void(int, const char*)>& failed, const std::function<void(int)>& progress = {});

} // namespace cmp
