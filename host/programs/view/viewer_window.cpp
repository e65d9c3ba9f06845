#include "viewer_window.hpp"

#include <glad/gl.h>
// GLFW must not include the system GL header: glad provides the GL declarations.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "keep_loaded.hpp"

namespace pfx::app {
namespace {

// GLFW reports errors through a callback; keep the last one for the message.
std::string g_last_glfw_error;

void remember_glfw_error(int code, const char* description) {
  g_last_glfw_error = std::string(description ? description : "unknown error") + " (GLFW error " + std::to_string(code) + ")";
}

GLADapiproc glad_loader(const char* name) { return reinterpret_cast<GLADapiproc>(glfwGetProcAddress(name)); }

}  // namespace

pfx_gl_proc ViewerWindow::get_proc_address(void*, const char* name) {
  return reinterpret_cast<pfx_gl_proc>(glfwGetProcAddress(name));
}

std::unique_ptr<ViewerWindow> ViewerWindow::create(int width, int height, const std::string& title, std::string* error) {
  auto fail = [&](const std::string& message) -> std::unique_ptr<ViewerWindow> {
    if (error) *error = "cannot open a window with an OpenGL 4.5 core context: " + message;
    return nullptr;
  };
  // GLFW and GLX load the GL driver and X libraries from here on; they stay loaded after
  // glfwTerminate (keep_loaded.hpp says why: no LeakSanitizer reports from unloaded modules).
  const std::vector<std::string> loaded_before = loaded_shared_objects();
  glfwSetErrorCallback(remember_glfw_error);
  if (!glfwInit())
    return fail(g_last_glfw_error + " - is there a display? Without one, run under xvfb-run (Debian package xvfb)");
  std::unique_ptr<ViewerWindow> self(new ViewerWindow);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  self->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!self->window_) return fail(g_last_glfw_error);
  keep_loaded_since(loaded_before);
  glfwMakeContextCurrent(self->window_);
  if (!gladLoadGL(glad_loader) || !GLAD_GL_VERSION_4_5) return fail("could not load the GL 4.5 entry points");
  // No vsync wait: a software renderer is slow enough, and scripted runs should not be paced.
  glfwSwapInterval(0);
  auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
  };
  self->renderer_ = text(GL_RENDERER) + " | " + text(GL_VERSION);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the user's folder: the layout is set in code
  ImGui::StyleColorsDark();
  self->imgui_glfw_ = ImGui_ImplGlfw_InitForOpenGL(self->window_, true);
  self->imgui_gl_ = self->imgui_glfw_ && ImGui_ImplOpenGL3_Init("#version 450 core");
  if (!self->imgui_gl_) return fail("Dear ImGui's GLFW or OpenGL 3 back-end failed to start");
  return self;
}

ViewerWindow::~ViewerWindow() {
  if (imgui_gl_) ImGui_ImplOpenGL3_Shutdown();
  if (imgui_glfw_) ImGui_ImplGlfw_Shutdown();
  if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

bool ViewerWindow::should_close() const { return glfwWindowShouldClose(window_); }
void ViewerWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void ViewerWindow::framebuffer_size(int* width, int* height) const { glfwGetFramebufferSize(window_, width, height); }

void ViewerWindow::poll_events(double wait_seconds) {
  if (wait_seconds > 0) glfwWaitEventsTimeout(wait_seconds);
  else glfwPollEvents();
}

void ViewerWindow::begin_ui_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ViewerWindow::draw_ui() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ViewerWindow::swap() { glfwSwapBuffers(window_); }

}  // namespace pfx::app
