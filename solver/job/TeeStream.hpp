#pragma once
// An output stream that writes to a file and, optionally, to a second stream (standard output):
// the message file is both the record of a run and what the user watches.

#include <ostream>
#include <streambuf>

namespace stella {

class TeeBuffer : public std::streambuf {
public:
  TeeBuffer(std::streambuf* first, std::streambuf* second) : first_(first), second_(second) {}

protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) {
      return traits_type::not_eof(c);
    }
    auto ch = static_cast<char>(c);
    if (first_->sputc(ch) == traits_type::eof()) {
      return traits_type::eof();
    }
    if (second_ != nullptr) {
      second_->sputc(ch);
    }
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    std::streamsize written = first_->sputn(s, n);
    if (second_ != nullptr) {
      second_->sputn(s, n);
    }
    return written;
  }
  int sync() override {
    int r = first_->pubsync();
    if (second_ != nullptr) {
      second_->pubsync();
    }
    return r;
  }

private:
  std::streambuf* first_;
  std::streambuf* second_;
};

} // namespace stella
