// SPDX-License-Identifier: MIT
// The progress line on stderr (progress_line.hpp). The library calls the
// callback every millisecond or so; the time check keeps the terminal's
// updates to ten a second, and the text is written with one fputs so that
// a line is never torn by the library's other output (there is none: the
// library never prints).
#include "progress_line.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "interrupt.hpp"

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

namespace cvms::cli {
namespace {

bool stderr_is_terminal() {
#if __has_include(<unistd.h>)
  return ::isatty(STDERR_FILENO) == 1;
#else
  return false;
#endif
}

// A line is open on the terminal (written without its newline). Only the
// command's thread and the library's calls (never two at once) touch it.
bool line_open = false;

class ProgressLine {
 public:
  // Off a terminal, the first line comes after a second, or at a stage's end.
  explicit ProgressLine(bool terminal)
      : terminal_(terminal),
        shown_(terminal ? std::chrono::steady_clock::time_point{} : std::chrono::steady_clock::now()) {}

  void show(const Progress& p) {
    const auto now = std::chrono::steady_clock::now();
    const bool last = p.done == p.total;
    if (!last && now - shown_ < (terminal_ ? terminal_interval : log_interval)) return;
    shown_ = now;
    const unsigned percent = p.total == 0 ? 100 : static_cast<unsigned>(p.done * 100 / p.total);
    std::string text = std::string("cvms: ") + p.stage + " " + std::to_string(percent) + "% (" +
                       std::to_string(p.done) + " of " + std::to_string(p.total) + ")";
    if (terminal_) {
      const std::size_t width = text.size();
      if (width < width_) text.append(width_ - width, ' ');  // over the longer line before
      width_ = last ? 0 : width;
      text.insert(0, "\r");
    }
    if (last || !terminal_) text += "\n";
    line_open = terminal_ && !last;
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
  }

 private:
  static constexpr std::chrono::milliseconds terminal_interval{100}, log_interval{1000};
  bool terminal_;
  std::size_t width_ = 0;
  std::chrono::steady_clock::time_point shown_;
};

}  // namespace

void add_progress_option(CLI::App& command, bool& forced) {
  command.add_flag("--progress", forced, "show progress on stderr (default: only when stderr is a terminal)");
}

ProgressCallback progress_callback(bool forced) {
  catch_interrupt();
  const bool terminal = stderr_is_terminal();
  if (!forced && !terminal) return [](const Progress&) { return !interrupted(); };
  auto line = std::make_shared<ProgressLine>(terminal);
  return [line](const Progress& p) {
    if (interrupted()) return false;
    line->show(p);
    return true;
  };
}

void finish_progress_line() {
  if (!line_open) return;
  std::fputs("\n", stderr);
  line_open = false;
}

}  // namespace cvms::cli
