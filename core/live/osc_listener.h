#pragma once
// The modeller's OSC input: a UDP socket bound to 127.0.0.1 only (nothing beyond
// this machine can reach it), its datagrams decoded by liblo on a thread of its own and queued
// for the UI thread, which applies them between frames. Two forms are taken:
// - "/gridifs/set ,sf PATH VALUE" (or ,sd / ,si): set any parameter within its range;
// - ADDRESS with one number (,f ,d or ,i): the value of bindings with source "osc:ADDRESS".
// Anything else (not OSC, bundles, other type tags) is counted as malformed and dropped.
//
// Thread-safety: take() and the counters may be called from any thread; the listener's thread
// only decodes and queues.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace gridifs {

struct OscInput {
  std::string address;                            // the OSC address
  std::string path;                               // "/gridifs/set": the parameter path
  double value = 0.0;                             // the number sent
  bool isSet = false;                             // "/gridifs/set"
  std::chrono::steady_clock::time_point arrived;  // when the datagram was read
};

class OscListener {
 public:
  /// Listens on 127.0.0.1:`port` (1..65535). `wake` is called on the listener's thread after
  /// each queued message (the modeller wakes its event loop with it). Throws IoError with one
  /// sentence when the port cannot be had.
  OscListener(int port, std::function<void()> wake = {});
  ~OscListener();
  OscListener(const OscListener&) = delete;
  OscListener& operator=(const OscListener&) = delete;

  int port() const { return port_; }
  /// The messages queued since the last call, oldest first.
  std::vector<OscInput> take();
  /// Datagrams received, and of those the ones dropped as malformed.
  std::int64_t received() const { return received_.load(std::memory_order_relaxed); }
  std::int64_t malformed() const { return malformed_.load(std::memory_order_relaxed); }

  /// Decodes one datagram (liblo); false when it is none of the two forms. For tests and the
  /// listener's thread.
  static bool decode(const void* data, std::size_t size, OscInput& out);

 private:
  void run();

  int port_ = 0;
  int socket_ = -1;
  std::function<void()> wake_;
  std::atomic<bool> stop_{false};
  std::atomic<std::int64_t> received_{0}, malformed_{0};
  std::mutex lock_;
  std::vector<OscInput> queue_;
  std::thread thread_;
};

}  // namespace gridifs
