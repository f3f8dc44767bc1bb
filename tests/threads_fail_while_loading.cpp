// Preloaded into rsaa by test_image_io (ImageModule.ThreadsFailingWhileItLoadsEndTheProcessWithAMessage):
// every pthread_create fails with EAGAIN while the image module loads, as when another process
// of the user reaches the process limit between rsaa's check and the load, a race that cannot
// be timed from outside.
#include <dlfcn.h>
#include <pthread.h>

#include <cerrno>
#include <cstring>

namespace {
thread_local int loading_image_module = 0;
}

extern "C" void* dlopen(const char* file, int mode) {
  using Open = void* (*)(const char*, int);
  static const Open real_dlopen = reinterpret_cast<Open>(dlsym(RTLD_NEXT, "dlopen"));
  const bool image_module = file && std::strstr(file, "rsaa_oiio") != nullptr;
  loading_image_module += image_module;
  void* module = real_dlopen(file, mode);
  loading_image_module -= image_module;
  return module;
}

extern "C" int pthread_create(pthread_t* thread, const pthread_attr_t* attributes, void* (*start)(void*),
                              void* argument) {
  using Create = int (*)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);
  static const Create real_create = reinterpret_cast<Create>(dlsym(RTLD_NEXT, "pthread_create"));
  if (loading_image_module) return EAGAIN;
  return real_create(thread, attributes, start, argument);
}
