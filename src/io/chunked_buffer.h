// An output stream buffer that keeps what is written in fixed-size chunks, for output that must be
// complete before any of it is shown (standard output, where a failed command writes nothing). Unlike an
// ostringstream it never moves what it holds: no doubling copies, and no final copy by str().
#pragma once

#include <memory>
#include <ostream>
#include <streambuf>
#include <vector>

namespace apollonius {

class Chunked_buffer : public std::streambuf {
 public:
  // Writes everything held so far to out, in order.
  void write_to(std::ostream& out) const;

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* text, std::streamsize count) override;

 private:
  static constexpr std::size_t kChunk = std::size_t{1} << 20;
  // Invariant: every chunk but the last is full; the put area is the last chunk's free part.
  std::vector<std::unique_ptr<char[]>> chunks_;
  void add_chunk();
};

}  // namespace apollonius
