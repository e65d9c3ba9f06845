// What a user (or a window manager) does to an application's window, done from a test on the test's
// X display (Xvfb, with no window manager and no other client): the top-level windows are the
// root's children, found by their size, since the applications here name none.
#pragma once

#include <string>

namespace pfx::test {

// The top-level windows, for a failure message: "300x300 mapped, 64x64 unmapped", or why there
// are none to tell.
std::string describe_windows();
// Each acts on the first top-level window of width x height; false when there is none.
bool window_exists(unsigned width, unsigned height);
bool resize_window(unsigned width, unsigned height, unsigned new_width, unsigned new_height);
// Unmapped and mapped again: what iconifying and restoring a window amounts to without a manager.
bool hide_window(unsigned width, unsigned height);
bool show_window(unsigned width, unsigned height);
// The window manager's "close" (WM_DELETE_WINDOW), as the title bar's button sends it.
bool close_window(unsigned width, unsigned height);
// Tries `act` every 0.1 s for up to `seconds` (an application maps its window some time after it
// starts); its last answer.
template <typename Act>
bool keep_trying(Act act, double seconds = 5);

}  // namespace pfx::test

#include <unistd.h>

template <typename Act>
bool pfx::test::keep_trying(Act act, double seconds) {
  for (double waited = 0;; waited += 0.1) {
    if (act()) return true;
    if (waited >= seconds) return false;
    usleep(100000);
  }
}
