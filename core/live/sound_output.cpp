#include "live/sound_output.h"

#include <SDL2/SDL.h>

#include <cmath>
#include <cstring>

namespace gridifs {

std::unique_ptr<SoundOutput> SoundOutput::open(std::string& why) {
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
    why = std::string("no audio output (") + SDL_GetError() + "): the timeline plays on a silent clock";
    return nullptr;
  }
  std::unique_ptr<SoundOutput> out(new SoundOutput);
  SDL_AudioSpec want{}, have{};
  want.freq = 48000;
  want.format = AUDIO_F32SYS;
  want.channels = 1;
  want.samples = 1024;
  want.callback = &SoundOutput::fill;
  want.userdata = out.get();
  out->device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, SDL_AUDIO_ALLOW_FREQUENCY_CHANGE);
  if (out->device_ == 0) {
    why = std::string("no audio output (") + SDL_GetError() + "): the timeline plays on a silent clock";
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    return nullptr;
  }
  out->deviceRate_ = have.freq;
  if (const char* driver = SDL_GetCurrentAudioDriver()) out->driver_ = driver;
  return out;
}

SoundOutput::~SoundOutput() {
  if (device_) SDL_CloseAudioDevice(device_);
  SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void SoundOutput::play(std::shared_ptr<const std::vector<float>> samples, double sampleRate, double fromSeconds) {
  SDL_LockAudioDevice(device_);
  samples_ = std::move(samples);
  sampleRate_ = sampleRate;
  step_ = sampleRate / double(deviceRate_);
  position_.store(std::max(0.0, fromSeconds * sampleRate));
  playing_ = true;
  SDL_UnlockAudioDevice(device_);
  SDL_PauseAudioDevice(device_, 0);
}

void SoundOutput::stop() {
  SDL_PauseAudioDevice(device_, 1);
  playing_ = false;
}

double SoundOutput::seconds() const { return sampleRate_ > 0.0 ? position_.load() / sampleRate_ : 0.0; }

void SoundOutput::fill(void* self, std::uint8_t* stream, int bytes) {
  auto* out = static_cast<SoundOutput*>(self);
  float* dst = reinterpret_cast<float*>(stream);
  const int n = bytes / int(sizeof(float));
  double pos = out->position_.load();
  const std::vector<float>* s = out->samples_.get();
  for (int i = 0; i < n; ++i, pos += out->step_) {
    // Linear interpolation between the sound's samples; silence past its end.
    const auto k = std::size_t(pos);
    if (!s || k + 1 >= s->size()) {
      dst[i] = 0.0f;
      continue;
    }
    const float f = float(pos - double(k));
    dst[i] = (*s)[k] + ((*s)[k + 1] - (*s)[k]) * f;
  }
  out->position_.store(pos);
}

}  // namespace gridifs
