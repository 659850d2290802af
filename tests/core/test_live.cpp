// Bindings and sound: sources parse, the file holds bindings and refuses bad ones
// with the parameter's own words, and the band envelope of synthetic sounds is what the
// definition says: silence gives exactly 0 (the binding's min), a tone in a band its max, and a
// tone in one band leaves another nearly still.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>
#include <vector>

#include "base/errors.h"
#include "edit/document.h"
#include "io/project_io.h"
#include "live/audio_envelope.h"
#include "live/live_drive.h"
#include "live/osc_listener.h"
#include "schema/live_binding.h"
#include "schema/project_parameter.h"
#include "tests/support/osc_packet.h"
#include "tests/support/sound_file.h"

namespace gridifs {
namespace {

namespace fs = std::filesystem;
using test_support::silenceThenTone;
using test_support::writeWav;

struct Scratch {
  fs::path path = fs::temp_directory_path() / ("gridifs-live-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(path); }
  ~Scratch() { fs::remove_all(path); }
};

Project boundProject() {
  Project p = defaultNewProject();
  p.animation = AnimationSettings{};
  p.audio = AudioSettings{"song.wav", {{20, 200}, {200, 2000}, {2000, 12000}}};
  p.bindings.push_back(Binding{"functions[0].weight", "audio:1", 0.5, 2.0, 0.0});
  p.bindings.push_back(Binding{"camera.yaw", "osc:/knob1", -180, 180, 0.0});
  p.bindings.push_back(Binding{"functions[0].resolution[0]", "midi:1:cc:7", 2, 10, 0.05});
  return p;
}

TEST(LiveBinding, SourcesParseInEveryFormAndRefuseTheRest) {
  EXPECT_EQ(parseBindingSource("audio:2")->band, 2);
  EXPECT_EQ(parseBindingSource("osc:/knob1")->address, "/knob1");
  const auto any = parseBindingSource("midi:cc:7");
  ASSERT_TRUE(any);
  EXPECT_EQ(any->kind, BindingSource::Kind::Midi);
  EXPECT_EQ(any->channel, 0);
  EXPECT_EQ(any->controller, 7);
  const auto channel = parseBindingSource("midi:16:cc:127");
  ASSERT_TRUE(channel);
  EXPECT_EQ(channel->channel, 16);
  EXPECT_EQ(channel->controller, 127);
  for (const char* bad : {"", "audio:", "audio:x", "osc:knob", "osc:/a b", "midi:cc:128", "midi:0:cc:1", "midi:17:cc:1",
                          "midi:1:nn:1", "keyboard:a"})
    EXPECT_FALSE(parseBindingSource(bad)) << bad;
}

TEST(LiveBinding, TheFileHoldsAudioAndBindings) {
  const Project p = boundProject();
  const std::string text = serializeProject(p);
  EXPECT_NE(text.find("\"bindings\""), std::string::npos);
  const Project back = parseProject(text);
  EXPECT_EQ(back.audio, p.audio);
  EXPECT_EQ(back.bindings, p.bindings);
  EXPECT_EQ(serializeProject(back), text);
}

/// The sentence reading `p` gives, or "" when it reads.
std::string liveRefusal(const Project& p) {
  try {
    parseProject(serializeProject(p));
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

TEST(LiveBinding, BadBindingsAreRefusedOnLoadWithOneSentence) {
  Project p = boundProject();
  p.bindings[0].path = "functions[7].weight";
  EXPECT_EQ(liveRefusal(p), "bindings[0].path: names no parameter of this project (functions[7].weight)");
  p = boundProject();
  p.bindings[1].source = "keyboard:a";
  EXPECT_NE(liveRefusal(p).find("bindings[1].source: expected a source like"), std::string::npos) << liveRefusal(p);
  p = boundProject();
  p.bindings[0].source = "audio:3";
  EXPECT_EQ(liveRefusal(p), "bindings[0].source: audio:3 names band 3, but \"audio\" has 3 bands");
  p = boundProject();
  p.audio.reset();
  EXPECT_EQ(liveRefusal(p), "bindings[0].source: audio:1 needs the project's \"audio\", and it has none");
  // A range end the parameter does not take gets the parameter's own words.
  p = boundProject();
  p.bindings[0].min = -1.0;
  Project direct = boundProject();
  std::string own;
  try {
    findParameter(direct, *TrackPath::parse("functions[0].weight")).parameter.set(direct, -1.0);
  } catch (const ModelError& e) {
    own = e.message();
  }
  ASSERT_FALSE(own.empty());
  EXPECT_EQ(liveRefusal(p), "bindings[0].min: " + own + " (the range of functions[0].weight)");
  p = boundProject();
  p.bindings[2].smooth = 61;
  EXPECT_NE(liveRefusal(p).find("bindings[2].smooth"), std::string::npos) << liveRefusal(p);
}

TEST(LiveBinding, AnEditThatRemovesTheNumberDropsItsBindingAndUndoBringsItBack) {
  Project p = defaultNewProject();
  p.functions.push_back(p.functions[0]);
  p.bindings.push_back(Binding{"functions[1].weight", "osc:/w", 0.0, 2.0, 0.0});
  p.bindings.push_back(Binding{"camera.yaw", "osc:/y", 0.0, 90.0, 0.0});
  Document document(p);
  document.apply(RemoveFunction{1});
  ASSERT_EQ(document.project().bindings.size(), 1u);
  EXPECT_EQ(document.project().bindings[0].path, "camera.yaw");
  // What is left reads back: the file reader would have refused the dangling binding.
  EXPECT_NO_THROW(parseProject(serializeProject(document.project())));
  document.undo();
  EXPECT_EQ(document.project().bindings.size(), 2u);
}

TEST(AudioEnvelope, SilenceIsExactlyZeroAndAToneInItsBandIsOne) {
  Scratch dir;
  const int rate = 44100;
  writeWav(dir.path / "tone.wav", silenceThenTone(1.0, 440.0, rate), rate);
  const AudioEnvelope e = analyseAudio(dir.path / "tone.wav", {{20, 200}, {200, 2000}, {2000, 12000}}, 24.0);
  ASSERT_EQ(e.frames(), 48);
  EXPECT_DOUBLE_EQ(e.seconds(), 2.0);
  for (int b = 0; b < 3; ++b)
    for (int k = 0; k < 24; ++k) EXPECT_EQ(e.energy[b][k], 0.0f) << "band " << b << " frame " << k;
  // The tone's band: its largest is 1, and every frame of the steady tone is near it.
  for (int k = 25; k < 48; ++k) EXPECT_NEAR(e.energy[1][k], 1.0f, 0.02f) << k;
  EXPECT_EQ(*std::max_element(e.energy[1].begin(), e.energy[1].end()), 1.0f);
  // Smoothing starts from silence and keeps it exact; it approaches the tone.
  const std::vector<float> smooth = e.smoothed(1, 0.05);
  for (int k = 0; k < 24; ++k) EXPECT_EQ(smooth[k], 0.0f);
  EXPECT_LT(smooth[24], 0.9f);
  EXPECT_GT(smooth[47], 0.98f);
}

TEST(AudioEnvelope, AToneInOneBandLeavesTheOthersNearlyStill) {
  Scratch dir;
  const int rate = 48000;
  // One second at 440 Hz, then one at 5 kHz, in stereo (the left channel only: mixed to mono).
  std::vector<float> stereo;
  for (int i = 0; i < 2 * rate; ++i) {
    const double hz = i < rate ? 440.0 : 5000.0;
    stereo.push_back(float(0.5 * std::sin(2.0 * M_PI * hz * i / rate)));
    stereo.push_back(0.0f);
  }
  writeWav(dir.path / "two.wav", stereo, rate, 2);
  const AudioEnvelope e = analyseAudio(dir.path / "two.wav", {{200, 2000}, {2000, 12000}}, 25.0);
  ASSERT_EQ(e.frames(), 50);
  for (int k = 2; k < 23; ++k) {
    EXPECT_NEAR(e.energy[0][k], 1.0f, 0.02f) << k;
    EXPECT_LT(e.energy[1][k], 0.01f) << k;
  }
  for (int k = 27; k < 48; ++k) {
    EXPECT_LT(e.energy[0][k], 0.01f) << k;
    EXPECT_NEAR(e.energy[1][k], 1.0f, 0.02f) << k;
  }
}

TEST(AudioEnvelope, UnreadableSoundsSayWhichFile) {
  Scratch dir;
  std::ofstream(dir.path / "noise.wav") << "not a sound";
  for (const char* name : {"missing.wav", "noise.wav"}) {
    try {
      analyseAudio(dir.path / name, {{20, 200}}, 24.0);
      ADD_FAILURE() << name;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(LiveDrive, BindingsSetTheirNumbersOverTheTracks) {
  Scratch dir;
  const int rate = 44100;
  writeWav(dir.path / "song.wav", silenceThenTone(1.0, 440.0, rate), rate);
  Project p = boundProject();
  // A track on the weight: the binding wins over it.
  p.tracks["functions[0].weight"].keys.push_back(Keyframe{0.0, 1.5});
  LiveDrive drive = LiveDrive::forProject(p, dir.path);
  ASSERT_TRUE(drive.envelope());
  Project silent = p;
  drive.applyBindings(silent, 0.5);
  EXPECT_EQ(silent.functions[0].weight, 0.5);  // exactly min
  Project loud = p;
  drive.applyBindings(loud, 1.5);
  EXPECT_NEAR(loud.functions[0].weight, 2.0, 0.03);
  Project after = p;
  drive.applyBindings(after, 10.0);  // past the sound: silence
  EXPECT_EQ(after.functions[0].weight, 0.5);
  // Live sources keep the project's value until a value comes; a controller on any channel
  // serves a binding to channel 1; whole numbers round.
  EXPECT_EQ(silent.camera.yaw, p.camera.yaw);
  drive.setLive("osc:/knob1", 0.75);
  drive.setLive("midi:cc:7", 64.0 / 127.0);
  Project live = p;
  drive.applyBindings(live, 0.0);
  EXPECT_DOUBLE_EQ(live.camera.yaw, 90.0);
  EXPECT_EQ(live.functions[0].resolution[0], 6);
}

TEST(OscListener, DecodesTheTwoFormsAndRefusesTheRest) {
  using test_support::OscPacket;
  OscInput in;
  auto decode = [&](const OscPacket& p) {
    const std::vector<char> b = p.bytes();
    return OscListener::decode(b.data(), b.size(), in);
  };
  ASSERT_TRUE(decode(OscPacket("/gridifs/set").s("camera.yaw").f(45.0f)));
  EXPECT_TRUE(in.isSet);
  EXPECT_EQ(in.path, "camera.yaw");
  EXPECT_EQ(in.value, 45.0);
  ASSERT_TRUE(decode(OscPacket("/knob1").f(0.25f)));
  EXPECT_FALSE(in.isSet);
  EXPECT_EQ(in.address, "/knob1");
  EXPECT_EQ(in.value, 0.25);
  ASSERT_TRUE(decode(OscPacket("/fader").i(1)));
  EXPECT_EQ(in.value, 1.0);
  EXPECT_FALSE(decode(OscPacket("/gridifs/set").f(1.0f)));                 // no path
  EXPECT_FALSE(decode(OscPacket("/gridifs/set").s("camera.yaw").s("x")));  // not a number
  EXPECT_FALSE(decode(OscPacket("/knob1").f(0.1f).f(0.2f)));               // two numbers
  EXPECT_FALSE(decode(OscPacket("/knob1").f(std::numeric_limits<float>::quiet_NaN())));
  const char garbage[] = "/x\0\0,zz";
  EXPECT_FALSE(OscListener::decode(garbage, sizeof garbage, in));
  const char bundle[] = "#bundle\0\0\0\0\0\0\0\0\1";
  EXPECT_FALSE(OscListener::decode(bundle, sizeof bundle, in));
}

TEST(OscListener, QueuesRealUdpMessagesOnLocalhostAndCountsMalformedOnes) {
  using test_support::OscPacket;
  const int port = test_support::freeUdpPort();
  std::atomic<int> wakes{0};
  OscListener listener(port, [&] { ++wakes; });
  ASSERT_TRUE(test_support::sendUdp(port, OscPacket("/knob1").f(0.5f).bytes()));
  ASSERT_TRUE(test_support::sendUdp(port, OscPacket("/gridifs/set").s("functions[0].weight").f(2.0f).bytes()));
  ASSERT_TRUE(test_support::sendUdp(port, std::vector<char>{'n', 'o', 'p', 'e'}));
  std::vector<OscInput> got;
  for (int i = 0; i < 200 && (got.size() < 2 || listener.malformed() < 1); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    for (OscInput& m : listener.take()) got.push_back(std::move(m));
  }
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].address, "/knob1");
  EXPECT_TRUE(got[1].isSet);
  EXPECT_EQ(got[1].path, "functions[0].weight");
  EXPECT_EQ(listener.received(), 3);
  EXPECT_EQ(listener.malformed(), 1);
  EXPECT_EQ(wakes.load(), 3);
  // The port is taken now: a second listener says so in one sentence.
  try {
    OscListener second(port);
    ADD_FAILURE() << "a second listener on one port";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot listen for OSC on 127.0.0.1:" + std::to_string(port)),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace gridifs
