// The number of threads a parallel step uses.
#pragma once

namespace apollonius {

// `requested` clamped to [1, the machine's concurrency]: an arena of more threads than TBB can run makes it
// print "number of workers is currently limited" to stderr (issue 21), and gains nothing.
int usable_threads(int requested);

}  // namespace apollonius
