#include "live/midi_input.h"

#include <rtmidi/RtMidi.h>
#include <unistd.h>

#include "base/errors.h"

namespace gridifs {

bool MidiInput::decode(const std::vector<unsigned char>& message, MidiControl& out) {
  // A control change: status 0xB0 | channel, controller, value (both 7-bit).
  if (message.size() != 3 || (message[0] & 0xF0) != 0xB0 || message[1] > 127 || message[2] > 127) return false;
  out.channel = (message[0] & 0x0F) + 1;
  out.controller = message[1];
  out.value = message[2];
  return true;
}

MidiInput::MidiInput(std::function<void()> wake) : wake_(std::move(wake)) {
  const bool alsa = ::access("/dev/snd/seq", R_OK | W_OK) == 0;
  system_ = alsa ? "ALSA" : "JACK";
  // With an error callback RtMidi reports problems there instead of throwing or printing.
  std::string problem;
  const std::string none = "no MIDI: this machine has no ALSA sequencer and no JACK server is running";
  try {
    in_ = std::make_unique<RtMidiIn>(alsa ? RtMidi::LINUX_ALSA : RtMidi::UNIX_JACK, "gridifs");
    in_->setErrorCallback(
        [](RtMidiError::Type type, const std::string& text, void* out) {
          if (type != RtMidiError::WARNING && type != RtMidiError::DEBUG_WARNING)
            *static_cast<std::string*>(out) = text;
        },
        &problem);
    in_->setCallback(&MidiInput::received, this);
    in_->ignoreTypes(true, true, true);  // sysex, timing and active sensing never reach the queue
    in_->openVirtualPort("midi-in");
  } catch (const RtMidiError& e) {
    problem = e.getMessage();
  }
  if (!problem.empty()) {
    in_.reset();
    throw IoError(alsa ? "cannot open a MIDI port in the ALSA sequencer: " + problem : none);
  }
}

MidiInput::~MidiInput() {
  if (in_) {
    in_->cancelCallback();
    in_->closePort();
  }
}

void MidiInput::received(double, std::vector<unsigned char>* message, void* self) {
  auto* input = static_cast<MidiInput*>(self);
  MidiControl control;
  {
    const std::lock_guard<std::mutex> hold(input->lock_);
    if (!message || !decode(*message, control)) {
      ++input->ignored_;
      return;
    }
    if (input->queue_.size() >= 4096) input->queue_.erase(input->queue_.begin());
    input->queue_.push_back(control);
  }
  if (input->wake_) input->wake_();
}

std::vector<MidiControl> MidiInput::take() {
  std::vector<MidiControl> out;
  const std::lock_guard<std::mutex> hold(lock_);
  out.swap(queue_);
  return out;
}

std::int64_t MidiInput::ignored() const {
  const std::lock_guard<std::mutex> hold(lock_);
  return ignored_;
}

}  // namespace gridifs
