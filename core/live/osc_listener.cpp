#include "live/osc_listener.h"

#include <arpa/inet.h>
#include <lo/lo.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "base/errors.h"

namespace gridifs {
namespace {

constexpr std::size_t kMaxQueued = 4096;  // past this, the oldest messages are dropped

/// A number argument of type tag `type`, or false.
bool number(char type, const lo_arg* arg, double& out) {
  switch (type) {
    case LO_FLOAT:
      out = arg->f;
      return true;
    case LO_DOUBLE:
      out = arg->d;
      return true;
    case LO_INT32:
      out = arg->i;
      return true;
    default:
      return false;
  }
}

}  // namespace

bool OscListener::decode(const void* data, std::size_t size, OscInput& out) {
  if (size < 4 || size > 65536 || static_cast<const char*>(data)[0] != '/') return false;  // bundles start with '#'
  // liblo's deserialiser takes a mutable buffer; it checks the padding and every argument.
  std::vector<char> copy(static_cast<const char*>(data), static_cast<const char*>(data) + size);
  int result = 0;
  lo_message message = lo_message_deserialise(copy.data(), copy.size(), &result);
  if (!message) return false;
  char* path = lo_get_path(copy.data(), ssize_t(copy.size()));
  bool ok = false;
  if (path) {
    const std::string address = path;
    const char* types = lo_message_get_types(message);
    lo_arg** argv = lo_message_get_argv(message);
    const int argc = lo_message_get_argc(message);
    out = OscInput{};
    out.address = address;
    if (address == "/gridifs/set") {
      out.isSet = true;
      ok = argc == 2 && types[0] == LO_STRING && number(types[1], argv[1], out.value);
      if (ok) out.path = &argv[0]->s;
    } else {
      ok = argc == 1 && number(types[0], argv[0], out.value);
    }
    ok = ok && std::isfinite(out.value);
  }
  lo_message_free(message);
  return ok;
}

OscListener::OscListener(int port, std::function<void()> wake) : port_(port), wake_(std::move(wake)) {
  if (port < 1 || port > 65535) throw IoError("--osc-port must be a port number from 1 to 65535");
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) throw IoError(std::string("cannot open a socket for OSC: ") + std::strerror(errno));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(std::uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // this machine only
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int error = errno;
    ::close(socket_);
    throw IoError("cannot listen for OSC on 127.0.0.1:" + std::to_string(port) + ": " + std::strerror(error));
  }
  thread_ = std::thread([this] { run(); });
}

OscListener::~OscListener() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
  ::close(socket_);
}

std::vector<OscInput> OscListener::take() {
  std::vector<OscInput> out;
  const std::lock_guard<std::mutex> hold(lock_);
  out.swap(queue_);
  return out;
}

void OscListener::run() {
  std::vector<char> buffer(65536);
  while (!stop_.load()) {
    pollfd fd{socket_, POLLIN, 0};
    // A short timeout so that the destructor's stop is seen promptly.
    if (::poll(&fd, 1, 50) <= 0) continue;
    const ssize_t n = ::recv(socket_, buffer.data(), buffer.size(), 0);
    if (n < 0) continue;
    received_.fetch_add(1, std::memory_order_relaxed);
    OscInput input;
    const auto arrived = std::chrono::steady_clock::now();
    if (!decode(buffer.data(), std::size_t(n), input)) {
      malformed_.fetch_add(1, std::memory_order_relaxed);
      if (wake_) wake_();
      continue;
    }
    input.arrived = arrived;
    {
      const std::lock_guard<std::mutex> hold(lock_);
      if (queue_.size() >= kMaxQueued) queue_.erase(queue_.begin());
      queue_.push_back(std::move(input));
    }
    if (wake_) wake_();
  }
}

}  // namespace gridifs
