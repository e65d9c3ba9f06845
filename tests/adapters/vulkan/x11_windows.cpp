#include "x11_windows.hpp"

#include <X11/Xlib.h>

#include <functional>

namespace pfx::test {
namespace {

// Calls `act` on the first top-level window of that size, then flushes; false when there is none.
bool with_window(unsigned width, unsigned height, const std::function<void(Display*, Window)>& act) {
  Display* display = XOpenDisplay(nullptr);
  if (!display) return false;
  Window root = DefaultRootWindow(display), parent = 0, *children = nullptr;
  unsigned count = 0;
  bool found = false;
  if (XQueryTree(display, root, &root, &parent, &children, &count)) {
    for (unsigned i = 0; i < count && !found; ++i) {
      XWindowAttributes attributes{};
      if (XGetWindowAttributes(display, children[i], &attributes) && unsigned(attributes.width) == width &&
          unsigned(attributes.height) == height) {
        act(display, children[i]);
        found = true;
      }
    }
    if (children) XFree(children);
  }
  XSync(display, False);
  XCloseDisplay(display);
  return found;
}

}  // namespace

std::string describe_windows() {
  Display* display = XOpenDisplay(nullptr);
  if (!display) return "the X display cannot be opened";
  Window root = DefaultRootWindow(display), parent = 0, *children = nullptr;
  unsigned count = 0;
  std::string text;
  if (XQueryTree(display, root, &root, &parent, &children, &count)) {
    for (unsigned i = 0; i < count; ++i) {
      XWindowAttributes attributes{};
      if (!XGetWindowAttributes(display, children[i], &attributes)) continue;
      text += (text.empty() ? "" : ", ") + std::to_string(attributes.width) + "x" + std::to_string(attributes.height) +
              (attributes.map_state == IsViewable ? " mapped" : " unmapped");
    }
    if (children) XFree(children);
  }
  XCloseDisplay(display);
  return text.empty() ? "no top-level window" : text;
}

bool window_exists(unsigned width, unsigned height) {
  return with_window(width, height, [](Display*, Window) {});
}

bool resize_window(unsigned width, unsigned height, unsigned new_width, unsigned new_height) {
  return with_window(width, height,
                     [&](Display* display, Window window) { XResizeWindow(display, window, new_width, new_height); });
}

bool hide_window(unsigned width, unsigned height) {
  return with_window(width, height, [](Display* display, Window window) { XUnmapWindow(display, window); });
}

bool show_window(unsigned width, unsigned height) {
  return with_window(width, height, [](Display* display, Window window) { XMapWindow(display, window); });
}

bool close_window(unsigned width, unsigned height) {
  return with_window(width, height, [](Display* display, Window window) {
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.window = window;
    event.xclient.message_type = XInternAtom(display, "WM_PROTOCOLS", False);
    event.xclient.format = 32;
    event.xclient.data.l[0] = long(XInternAtom(display, "WM_DELETE_WINDOW", False));
    event.xclient.data.l[1] = CurrentTime;
    XSendEvent(display, window, False, NoEventMask, &event);
  });
}

}  // namespace pfx::test
