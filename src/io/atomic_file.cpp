#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <streambuf>
#include <utility>

namespace apollonius {

namespace {

Output_error write_error(const std::string& path, int error_number) {
  return Output_error("cannot write " + path + ": " + std::strerror(error_number));
}

// A stream buffer over a POSIX file descriptor: std::ofstream gives neither the descriptor that fsync
// needs nor errno's reason when a write fails.
class File_descriptor_buffer : public std::streambuf {
 public:
  explicit File_descriptor_buffer(int descriptor) : descriptor_(descriptor) { reset_buffer(); }

  // errno of the first failed write, 0 while every write succeeded.
  int error_number() const { return error_number_; }

 protected:
  int_type overflow(int_type c) override {
    if (!write_buffer()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }

  int sync() override { return write_buffer() ? 0 : -1; }

 private:
  void reset_buffer() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }

  bool write_buffer() {
    const char* next = pbase();
    while (next < pptr()) {
      const ssize_t written = ::write(descriptor_, next, static_cast<std::size_t>(pptr() - next));
      if (written < 0) {
        if (errno == EINTR) continue;
        error_number_ = errno;
        return false;
      }
      next += written;
      written_ += static_cast<std::size_t>(written);
    }
    reset_buffer();
    // Starts the disk writes of each few MiB as soon as they are written (a hint: fsync in commit()
    // waits for them and reports errors), so that the final fsync of a large output (the whole diagram
    // of a protein, 14 MB) overlaps with the formatting instead of following it.
    if (written_ - written_back_ >= kWritebackChunk) {
      ::sync_file_range(descriptor_, static_cast<off_t>(written_back_), static_cast<off_t>(written_ - written_back_),
                        SYNC_FILE_RANGE_WRITE);
      written_back_ = written_;
    }
    return true;
  }

  static constexpr std::size_t kWritebackChunk = std::size_t{4} << 20;
  int descriptor_;
  int error_number_ = 0;
  std::size_t written_ = 0, written_back_ = 0;  // bytes written; those whose writeback was started
  std::array<char, 1 << 16> buffer_;
};

// A new file beside the target, removed on destruction unless commit() renamed it over the target.
class Temporary_file {
 public:
  // Not mkstemp: it creates the file with mode 0600, and the output should get the usual
  // 0666 & ~umask. O_EXCL with the process id and a counter gives a name nobody else holds.
  explicit Temporary_file(std::string target) : target_(std::move(target)) {
    static std::atomic<unsigned long> counter{0};
    for (;;) {
      path_ = target_ + ".tmp" + std::to_string(::getpid()) + "." + std::to_string(counter++);
      descriptor_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (descriptor_ >= 0) return;
      if (errno != EEXIST) throw write_error(target_, errno);  // else a stale temporary: try the next name
    }
  }
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;
  ~Temporary_file() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!committed_) ::unlink(path_.c_str());
  }

  int descriptor() const { return descriptor_; }

  // fsync before rename, so that after a crash the target holds its old content or the whole new one.
  void commit() {
    if (::fsync(descriptor_) != 0) throw write_error(target_, errno);
    const int closed = ::close(descriptor_);
    descriptor_ = -1;
    if (closed != 0) throw write_error(target_, errno);
    if (::rename(path_.c_str(), target_.c_str()) != 0) throw write_error(target_, errno);
    committed_ = true;
  }

 private:
  std::string target_;
  std::string path_;
  int descriptor_ = -1;
  bool committed_ = false;
};

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  Temporary_file temporary(path);
  {
    File_descriptor_buffer buffer(temporary.descriptor());
    std::ostream out(&buffer);
    write(out);
    out.flush();
    if (!out) {
      if (buffer.error_number() != 0) throw write_error(path, buffer.error_number());
      throw Output_error("cannot write " + path + ": output stream failed");
    }
  }
  temporary.commit();
}

}  // namespace apollonius
