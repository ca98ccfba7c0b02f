#include "io/chunked_buffer.h"

#include <algorithm>
#include <cstring>

namespace apollonius {

void Chunked_buffer::add_chunk() {
  chunks_.push_back(std::make_unique<char[]>(kChunk));
  setp(chunks_.back().get(), chunks_.back().get() + kChunk);
}

Chunked_buffer::int_type Chunked_buffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  add_chunk();
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

std::streamsize Chunked_buffer::xsputn(const char* text, std::streamsize count) {
  for (std::streamsize left = count; left > 0;) {
    if (pptr() == epptr()) add_chunk();
    const std::streamsize room = std::min<std::streamsize>(left, epptr() - pptr());
    std::memcpy(pptr(), text, static_cast<std::size_t>(room));
    pbump(static_cast<int>(room));
    text += room;
    left -= room;
  }
  return count;
}

void Chunked_buffer::write_to(std::ostream& out) const {
  for (std::size_t i = 0; i < chunks_.size(); ++i)
    out.write(chunks_[i].get(), static_cast<std::streamsize>(i + 1 < chunks_.size() ? kChunk : pptr() - pbase()));
}

}  // namespace apollonius
