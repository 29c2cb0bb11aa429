// SPDX-License-Identifier: MIT
// Loads the plugin (plugin.cpp) with dlopen, as an application loads its
// plugins, and runs it on the main thread and on a second one, so that the
// library's thread-local data is set up in a loaded module for both.
// Usage: cvms_plugin_host PATH_TO_PLUGIN_SO. Exits 0 when both runs pass.
#include <dlfcn.h>

#include <cstdio>
#include <thread>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s PLUGIN.so\n", argv[0]);
    return 2;
  }
  void* handle = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    std::fprintf(stderr, "plugin host: dlopen: %s\n", dlerror());
    return 1;
  }
  using Run = int (*)();
  const auto run = reinterpret_cast<Run>(dlsym(handle, "cvms_plugin_run"));
  if (run == nullptr) {
    std::fprintf(stderr, "plugin host: dlsym: %s\n", dlerror());
    return 1;
  }
  const int on_main = run();
  int on_thread = -1;
  std::thread([&] { on_thread = run(); }).join();
  std::printf("plugin host: main thread %d, second thread %d (%s)\n", on_main, on_thread,
              on_main == 0 && on_thread == 0 ? "ok" : "FAILED");
  return on_main == 0 && on_thread == 0 ? 0 : 1;
}
