#pragma once
// An output stream that hands each line written to it to a C callback (flexmoor_set_logger),
// without its newline, and keeps the lines since clear() (a failure's diagnosis, for the
// handle's message).
#include <ostream>
#include <streambuf>
#include <string>

namespace flexmoor::capi {

using LogFunction = void (*)(void* user_data, int level, const char* line);

class LogLines final : public std::streambuf {
 public:
  explicit LogLines(int level) : level_(level) {}
  void setCallback(LogFunction log, void* user_data) {
    log_ = log;
    user_data_ = user_data;
  }
  // The lines written since the last clear(), each ended by a newline.
  const std::string& kept() const { return kept_; }
  void clear() { kept_.clear(); }

 protected:
  int_type overflow(int_type ch) override {
    if (ch == traits_type::eof()) return traits_type::not_eof(ch);
    if (ch == '\n') {
      if (log_) log_(user_data_, level_, line_.c_str());
      kept_ += line_ + "\n";
      line_.clear();
    } else {
      line_.push_back(static_cast<char>(ch));
    }
    return ch;
  }

 private:
  int level_;
  LogFunction log_ = nullptr;
  void* user_data_ = nullptr;
  std::string line_, kept_;
};

// LogLines with its stream.
struct LogStream {
  explicit LogStream(int level) : lines(level), stream(&lines) {}
  LogLines lines;
  std::ostream stream;
};

}  // namespace flexmoor::capi
