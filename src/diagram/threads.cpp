#include "diagram/threads.h"

#include <tbb/task_arena.h>

#include <algorithm>

namespace apollonius {

int usable_threads(int requested) { return std::clamp(requested, 1, tbb::this_task_arena::max_concurrency()); }

}  // namespace apollonius
