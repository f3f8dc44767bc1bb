#include "runtime/scene.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <future>
#include <stdexcept>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "runtime/allocation_budget.h"

namespace rsaa {

glm::vec3 Scene::bounds_min() const {
  glm::vec3 lo(std::numeric_limits<float>::max());
  for (std::uint32_t i : indices) lo = glm::min(lo, vertices[i].position);
  return lo;
}

glm::vec3 Scene::bounds_max() const {
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  for (std::uint32_t i : indices) hi = glm::max(hi, vertices[i].position);
  return hi;
}

Scene load_scene(const std::string& spec) {
  const std::string prefix = "builtin:";
  if (spec.rfind(prefix, 0) == 0) return builtin_scene(spec.substr(prefix.size()));
  return load_model(spec);
}

namespace {

// What the loader thread hands back; shared, since a thread that times out outlives the call.
struct LoadState {
  std::string spec;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::optional<Scene> scene;
  std::exception_ptr error;
  int child = 0;  // the import's process while it runs
};

// The last line of defence against nesting deeper than even the loader's large stack (a glTF
// node chain of 1.5 million levels needs more than 512 MiB): a fault just below the loader
// thread's stack ends the process with a message naming the scene, instead of a bare SIGSEGV.
thread_local std::uintptr_t t_stack_low = 0;
thread_local std::size_t t_stack_size = 0;
thread_local char t_overflow_message[640];
thread_local std::size_t t_overflow_length = 0;
// The same for an importer that uses a null pointer from a malloc the import's budget refused
// (allocation_budget.h: a refused malloc returns null; pugixml, zlib and minizip check, code that
// does not faults).
thread_local char t_refused_message[640];
thread_local std::size_t t_refused_length = 0;
// Where the messages go: stderr, or in an import's child process the pipe to the parent.
thread_local int t_fault_fd = 2;
struct sigaction g_previous_segv;

void on_segv(int signal, siginfo_t* info, void* context) {
  const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
  if (t_stack_low != 0 && address < t_stack_low + 65536 && address + (std::uintptr_t{1} << 20) > t_stack_low) {
    [[maybe_unused]] const ssize_t n = ::write(t_fault_fd, t_overflow_message, t_overflow_length);
    ::_exit(1);
  }
  const AllocationBudget* budget = t_stack_low != 0 ? AllocationBudget::on_this_thread() : nullptr;
  if (budget && budget->refused_request() != 0) {
    [[maybe_unused]] const ssize_t n = ::write(t_fault_fd, t_refused_message, t_refused_length);
    ::_exit(1);
  }
  // Not a loader overflow: hand the fault to whoever handled it before (by default, a crash).
  ::sigaction(signal, &g_previous_segv, nullptr);
  (void)context;
}

// The guard's messages: "rsaa: error: TEXT\n" on stderr, or kFault + TEXT into an import's pipe.
constexpr char kFault = 'F';
void set_fault_messages(const std::string& spec, std::size_t stack_bytes, int fd) {
  const std::string head = fd == 2 ? "rsaa: error: '" : std::string(1, kFault) + "model '";
  const std::string tail = fd == 2 ? "\n" : "";
  const std::string message = head + spec.substr(0, 400) + "': nested too deeply: the model importer overflowed its " +
                              std::to_string(stack_bytes >> 20) + " MiB stack" + tail;
  t_overflow_length = std::min(message.size(), sizeof t_overflow_message);
  std::memcpy(t_overflow_message, message.data(), t_overflow_length);
  const std::string refused = head + spec.substr(0, 400) +
                              "': the model importer crashed on an allocation its memory budget refused: "
                              "the file declares more data than it holds" + tail;
  t_refused_length = std::min(refused.size(), sizeof t_refused_message);
  std::memcpy(t_refused_message, refused.data(), t_refused_length);
  t_fault_fd = fd;
}

void guard_loader_stack(const std::string& spec, std::vector<char>& alternate_stack) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    struct sigaction action {};
    action.sa_sigaction = on_segv;
    action.sa_flags = SA_SIGINFO | SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGSEGV, &action, &g_previous_segv);
  });
  stack_t alternate{};
  alternate.ss_sp = alternate_stack.data();
  alternate.ss_size = alternate_stack.size();
  if (::sigaltstack(&alternate, nullptr) != 0) return;
  pthread_attr_t attributes;
  if (pthread_getattr_np(pthread_self(), &attributes) != 0) return;
  void* low = nullptr;
  std::size_t size = 0;
  pthread_attr_getstack(&attributes, &low, &size);
  pthread_attr_destroy(&attributes);
  t_stack_size = size;
  set_fault_messages(spec, size, 2);
  t_stack_low = reinterpret_cast<std::uintptr_t>(low);
}

void* run_loader(void* argument) {
  const std::shared_ptr<LoadState> state = *static_cast<std::shared_ptr<LoadState>*>(argument);
  delete static_cast<std::shared_ptr<LoadState>*>(argument);
  std::vector<char> alternate_stack(std::max<std::size_t>(SIGSTKSZ, 64 * 1024));
  guard_loader_stack(state->spec, alternate_stack);
  std::optional<Scene> scene;
  std::exception_ptr error;
  try {
    if (state->spec.rfind("builtin:", 0) == 0) {
      scene = load_scene(state->spec);
    } else {
      scene = with_textures(import_model_in_child(state->spec, [&](int pid) {
        const std::lock_guard<std::mutex> lock(state->mutex);
        state->child = pid;
      }));
    }
  } catch (...) {
    error = std::current_exception();
  }
  t_stack_low = 0;
  stack_t off{};
  off.ss_flags = SS_DISABLE;
  ::sigaltstack(&off, nullptr);
  const std::lock_guard<std::mutex> lock(state->mutex);
  state->scene = std::move(scene);
  state->error = error;
  state->done = true;
  state->finished.notify_all();
  return nullptr;
}

}  // namespace

namespace {

// The imported model as bytes through the pipe: the scene's name, vertices, indices and draws,
// then the texture sources. Its parts are plain data (SceneVertex, DrawRange: no pointers).
constexpr char kImported = 'S', kRefused = 'E';
// Above what a model within the budgets needs (2^24 vertices of 48 bytes, 2^25 triangles, its
// files): a child that sends more is not trusted.
constexpr std::uint64_t kMaxImportBytes = std::uint64_t{3} << 30;

template <class T>
void put(std::string& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}
void put(std::string& out, const std::string& text) { put(out, std::vector<char>(text.begin(), text.end())); }

struct Reader {
  const std::string& bytes;
  std::size_t at = 0;
  template <class T>
  std::vector<T> vector() {
    std::uint64_t n = 0;
    take(&n, sizeof n);
    if (n > (bytes.size() - at) / sizeof(T)) throw std::runtime_error("the import's result is cut short");
    std::vector<T> v(n);
    take(v.data(), n * sizeof(T));
    return v;
  }
  std::string text() {
    const std::vector<char> v = vector<char>();
    return std::string(v.begin(), v.end());
  }
  void take(void* to, std::size_t n) {
    if (n > bytes.size() - at) throw std::runtime_error("the import's result is cut short");
    if (n) std::memcpy(to, bytes.data() + at, n);
    at += n;
  }
};

std::string serialized(const ImportedModel& m) {
  std::string out(1, kImported);
  put(out, m.scene.name);
  put(out, m.scene.vertices);
  put(out, m.scene.indices);
  put(out, m.scene.draws);
  put(out, std::vector<char>(m.textures.size()));
  for (const TextureSource& t : m.textures) {
    put(out, t.name), put(out, t.bytes), put(out, t.format_hint);
    out += char(t.embedded);
  }
  return out;
}

ImportedModel deserialized(const std::string& bytes) {
  Reader in{bytes, 1};
  ImportedModel m;
  m.scene.name = in.text();
  m.scene.vertices = in.vector<SceneVertex>();
  m.scene.indices = in.vector<std::uint32_t>();
  m.scene.draws = in.vector<DrawRange>();
  m.textures.resize(in.vector<char>().size());
  for (TextureSource& t : m.textures) {
    t.name = in.text(), t.bytes = in.text(), t.format_hint = in.text();
    char embedded = 0;
    in.take(&embedded, 1);
    t.embedded = embedded != 0;
  }
  return m;
}

bool write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += std::size_t(n);
  }
  return true;
}

}  // namespace

ImportedModel import_model_in_child(const std::string& path, const std::function<void(int pid)>& started) {
  const std::string what = "model '" + path + "'";
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(what + ": cannot start its import (pipe: " + std::strerror(errno) + ")");
  std::fflush(nullptr);  // else a child that ends through exit or abort may write the parent's buffers again
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]), ::close(fds[1]);
    throw std::runtime_error(what + ": cannot start its import (fork: " + std::strerror(error) +
                             "; a process or memory limit?)");
  }
  if (pid == 0) {
    // The child: one thread, a copy of the loader's (its large stack and fault guard). Leaves
    // with _exit: the parent's atexit handlers and static objects are not the child's to run.
    ::close(fds[0]);
    if (t_stack_low != 0) set_fault_messages(path, t_stack_size, fds[1]);
    std::string result;
    try {
      result = serialized(import_model(path));
    } catch (const std::bad_alloc&) {
      result = std::string(1, kRefused) + what + ": out of memory while importing it (an address-space limit, ulimit -v?)";
    } catch (const std::exception& e) {
      result = std::string(1, kRefused) + e.what();
    } catch (...) {
      result = std::string(1, kRefused) + what + ": the import failed";
    }
    ::_exit(write_all(fds[1], result) ? 0 : 1);
  }
  ::close(fds[1]);
  if (started) started(pid);
  std::string bytes;
  std::string refusal;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (bytes.size() + std::size_t(n) > kMaxImportBytes) {
      refusal = what + ": its import sent more than " + std::to_string(kMaxImportBytes >> 20) + " MiB";
      ::kill(pid, SIGKILL);
      break;
    }
    bytes.append(buffer, std::size_t(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (started) started(0);  // reaped: its PID may be reused, not to be killed any more
  if (!refusal.empty()) throw std::runtime_error(refusal);
  if (!bytes.empty() && (bytes[0] == kRefused || bytes[0] == kFault)) throw std::runtime_error(bytes.substr(1));
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    throw std::runtime_error(what + ": the model importer (assimp) " +
                             (signal == SIGKILL ? std::string("was killed (SIGKILL: a time or memory limit)")
                                                : "crashed on it (signal " + std::to_string(signal) + ", " +
                                                      sigabbrev_np(signal) + "): the file is malformed"));
  }
  if (bytes.empty() || bytes[0] != kImported || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(what + ": its import ended without a result (status " + std::to_string(status) + ")");
  return deserialized(bytes);
}

Scene load_scene_within(const std::string& spec, double seconds) {
  auto state = std::make_shared<LoadState>();
  state->spec = spec;
  // pthread, not std::thread: only pthread attributes set the stack size. Under a tight
  // address-space limit the full stack may not fit: smaller ones are tried (the fault guard
  // still names the scene if one overflows).
  auto* argument = new std::shared_ptr<LoadState>(state);
  pthread_t thread;
  int error = EAGAIN;
  for (std::size_t stack = kLoaderStackBytes; error != 0 && stack >= (std::size_t{16} << 20); stack /= 4) {
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    pthread_attr_setstacksize(&attributes, stack);
    error = pthread_create(&thread, &attributes, run_loader, argument);
    pthread_attr_destroy(&attributes);
  }
  if (error != 0) {
    delete argument;
    throw std::runtime_error("'" + spec + "': cannot start the loader thread (" +
                             std::strerror(error) + "; a process or memory limit?)");
  }
  pthread_detach(thread);
  std::unique_lock<std::mutex> lock(state->mutex);
  if (!state->finished.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return state->done; })) {
    if (state->child > 0) ::kill(state->child, SIGKILL);  // the loader thread then ends too
    throw std::runtime_error("'" + spec + "': loading did not finish within " +
                             std::to_string(int(seconds)) + " s (a malformed file can make the "
                             "model importer loop forever)");
  }
  if (state->error) std::rethrow_exception(state->error);
  return std::move(*state->scene);
}

void check_frameable(const Scene& scene, const std::string& what) {
  const glm::dvec3 lo = scene.bounds_min(), hi = scene.bounds_max();
  double largest = 0.0, extent = 0.0;
  for (int k = 0; k < 3; ++k) {
    largest = std::max({largest, std::abs(lo[k]), std::abs(hi[k])});
    extent = std::max(extent, hi[k] - lo[k]);
  }
  char text[160];
  if (!(largest <= kMaxSceneCoordinate)) {
    std::snprintf(text, sizeof text, "coordinates reach %g; models render correctly up to %g", largest,
                  kMaxSceneCoordinate);
  } else if (!(extent >= kMinSceneExtent)) {
    std::snprintf(text, sizeof text, "extent %g is below %g, too small to render correctly in float", extent,
                  kMinSceneExtent);
  } else if (extent < largest * kMinExtentToPosition) {
    std::snprintf(text, sizeof text, "extent %g at %g from the origin spans too few float steps (needs at least %g of the distance)",
                  extent, largest, kMinExtentToPosition);
  } else {
    return;
  }
  throw std::runtime_error(what + ": " + text);
}

Scene scaled_scene(Scene scene, float factor) {
  if (!(factor > 0.0f) || !std::isfinite(factor)) throw std::invalid_argument("scene scale must be a finite number > 0 that a float holds (1.2e-38 to 3.4e+38)");
  if (factor == 1.0f) return scene;
  for (SceneVertex& v : scene.vertices) v.position *= factor;
  if (scene.camera) {
    scene.camera->eye *= factor, scene.camera->target *= factor;
    scene.camera->near_plane *= factor, scene.camera->far_plane *= factor;
  }
  // Scaled out of the range that renders correctly in float, it would show only the background.
  char what[64];
  std::snprintf(what, sizeof what, "scene scaled by %g", double(factor));
  check_frameable(scene, "'" + scene.name + "' " + what);
  return scene;
}

std::string scene_short_name(const std::string& spec) {
  const std::string name = spec.substr(spec.find_last_of("/:") + 1);
  std::string short_name = name.substr(0, name.find('.'));
  // A part of file names (pareto-NAME.png) and of reports' lines: no control characters (a
  // newline in a model's path made two lines of one name).
  for (char& c : short_name)
    if (std::iscntrl(static_cast<unsigned char>(c))) c = '_';
  return short_name;
}

Camera choose_camera(const Scene& scene, const std::optional<Camera>& requested) {
  if (requested) return *requested;
  if (scene.camera) return *scene.camera;
  return frame_bounds(scene.bounds_min(), scene.bounds_max());
}

}  // namespace rsaa
