// Fresh memory about to be written in one sweep.
#pragma once

#include <cstddef>

namespace apollonius {

// Asks the system to back the whole pages of [begin, begin + bytes) at once, ready for writing, instead of
// one page fault at a time as they are first written (Linux 5.14 and later; elsewhere, and on failure, it
// does nothing). Only advice: what the memory holds is unchanged.
void populate_for_writing(void* begin, std::size_t bytes);

}  // namespace apollonius
