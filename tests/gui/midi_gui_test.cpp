// MIDI through a real transport: JACK's server with its dummy driver (userspace, no sound
// hardware; these machines have no ALSA sequencer), started and stopped here by process id. The
// artist right-clicks the field of view's key button, picks "Bind…", moves a controller (RtMidi
// playing one), and the controller then drives the field of view over its slider's range.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <rtmidi/RtMidi.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/gui/gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// A JACK server of its own name with the dummy driver, for as long as this object lives.
class JackDummyServer {
 public:
  JackDummyServer()
      : name_("gridifs-test-" + std::to_string(::getpid())),
        log_((std::filesystem::temp_directory_path() / (name_ + ".log")).string()) {
    if (run("command -v jackd >/dev/null") != 0) {
      problem_ = "jackd is not installed (scripts/deps.sh installs jackd2)";
      return;
    }
    ::setenv("JACK_DEFAULT_SERVER", name_.c_str(), 1);  // this process and the modeller it starts
    ::setenv("JACK_NO_AUDIO_RESERVATION", "1", 1);
    pid_ = ::fork();
    if (pid_ == 0) {
      const int log = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(log, 1);
      ::dup2(log, 2);
      // A loaded test machine (two GUI shards on two cores) can stall a client's process thread
      // past JACK's default 500 ms client timeout; give clients 5 s, and wake them a quarter as
      // often as a 256-frame period would.
      ::execlp("jackd", "jackd", "--no-realtime", "--timeout", "5000", "-n", name_.c_str(), "-d", "dummy", "-r",
               "48000", "-p", "1024", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    for (int i = 0; i < 100; ++i) {
      if (run("jack_lsp -s " + name_ + " >/dev/null 2>&1") == 0) return;
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        problem_ = "jackd exited at once (status " + std::to_string(status) + "): it cannot run on this machine";
        return;
      }
      std::this_thread::sleep_for(100ms);
    }
    problem_ = "jackd did not answer within 10 s";
  }
  ~JackDummyServer() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
    ::unsetenv("JACK_DEFAULT_SERVER");
    std::filesystem::remove(log_);
  }
  const std::string& problem() const { return problem_; }
  /// What the server printed, for a failure's message (a client it dropped shows here).
  std::string log() const {
    std::ifstream in(log_);
    return "jackd printed:\n" + std::string(std::istreambuf_iterator<char>(in), {});
  }

 private:
  std::string name_, log_, problem_;
  pid_t pid_ = -1;
};

/// Sends control change `controller` = `value` on channel 1 to the modeller's MIDI port.
void sendControl(RtMidiOut& out, int controller, int value) {
  std::vector<unsigned char> message{0xB0, static_cast<unsigned char>(controller), static_cast<unsigned char>(value)};
  out.sendMessage(&message);
}

}  // namespace

TEST(MidiGui, ALearntControllerDrivesTheFieldOfView) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  JackDummyServer jack;
  ASSERT_TRUE(jack.problem().empty()) << "MIDI needs JACK's dummy server: " << jack.problem();
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  App app(home, {project.string(), "--midi"});
  nlohmann::json probe = app.waitForPreview();
  probe = app.waitFor([](const nlohmann::json& j) { return j["live"]["midi"] == "JACK"; });
  ASSERT_EQ(probe["live"]["midi"], "JACK") << probe["live"]["midi_problem"];

  // The controller: RtMidi's JACK output, connected to the modeller's port.
  RtMidiOut out(RtMidi::UNIX_JACK, "controller");
  int port = -1;
  for (unsigned i = 0; i < out.getPortCount(); ++i)
    if (out.getPortName(i).find("gridifs:midi-in") != std::string::npos) port = int(i);
  ASSERT_GE(port, 0) << "the modeller's MIDI port";
  out.openPort(unsigned(port));

  // Right-click the field of view's key button, "Bind…", then move controller 7.
  clickRect(rectOf(probe, "preview.camera"));
  const auto key = app.waitForStableRect("key.camera.fov");
  ASSERT_TRUE(key) << "the Camera window opens";
  xdotool("mousemove " + std::to_string(key->x + key->w / 2) + " " + std::to_string(key->y + key->h / 2) + " click 3");
  const auto bind = app.waitForStableRect("key.bind");
  ASSERT_TRUE(bind) << "the key button's menu offers Bind...";
  clickAt(bind->x + bind->w / 2, bind->y + bind->h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["live"]["learning"] == "camera.fov"; });
  ASSERT_EQ(probe["live"]["learning"], "camera.fov");
  sendControl(out, 7, 64);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Bind camera.fov"; });
  ASSERT_EQ(probe["live"]["bindings"].size(), 1u);
  EXPECT_EQ(probe["live"]["bindings"][0]["source"], "midi:1:cc:7");
  const double lo = probe["live"]["bindings"][0]["min"], hi = probe["live"]["bindings"][0]["max"];
  EXPECT_LT(lo, hi);

  // The controller's ends are the slider's ends; no undo steps for the moves.
  sendControl(out, 7, 127);
  probe = app.waitFor([&](const nlohmann::json& j) { return j["camera"]["fov"] == hi; });
  EXPECT_EQ(probe["camera"]["fov"], hi) << probe["live"].dump() << "\n" << jack.log();
  sendControl(out, 7, 0);
  probe = app.waitFor([&](const nlohmann::json& j) { return j["camera"]["fov"] == lo; });
  EXPECT_EQ(probe["camera"]["fov"], lo) << probe["live"].dump() << "\n" << jack.log();
  EXPECT_EQ(probe["undo"], "Bind camera.fov");
  // Another controller moves nothing bound.
  sendControl(out, 8, 100);
  std::this_thread::sleep_for(300ms);
  EXPECT_EQ(app.probe()["camera"]["fov"], lo);
}
