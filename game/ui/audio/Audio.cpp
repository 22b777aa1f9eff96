#include "game/ui/audio/Audio.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include "game/ui/view/ForceCues.h"

namespace hemiroll::game {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A cue as a few notes: (start [s], frequency [Hz]), each decaying.
struct Note {
  double start, frequency;
};
struct CueShape {
  Note notes[3];
  int count;
  double length;  // [s]
};
constexpr CueShape kShapes[] = {
    {{{0.0, 523.25}, {0.12, 659.25}, {0.24, 783.99}}, 3, 0.9},  // success: C5 E5 G5
    {{{0.0, 392.0}, {0.18, 311.13}, {0.36, 233.08}}, 3, 0.9},   // failure: falling
    {{{0.0, 1800.0}}, 1, 0.03},                                  // engage click
    {{{0.0, 900.0}}, 1, 0.03},                                   // disengage click
};

}  // namespace

SoundOutputs SoundOutputs::probe() {
  SoundOutputs o;
  const char* driver = std::getenv("SDL_AUDIODRIVER");
  o.driverChosen = driver != nullptr && *driver != '\0';
  std::error_code ec;
  const char* runtime = std::getenv("XDG_RUNTIME_DIR");
  o.soundServer = std::getenv("PULSE_SERVER") != nullptr || std::filesystem::exists("/run/pulse/native", ec) ||
                  (runtime && (std::filesystem::exists(std::filesystem::path(runtime) / "pulse" / "native", ec) ||
                               std::filesystem::exists(std::filesystem::path(runtime) / "pipewire-0", ec)));
  std::ifstream cards("/proc/asound/cards");
  if (cards) {
    o.cardListRead = true;
    o.cardList.assign(std::istreambuf_iterator<char>(cards), std::istreambuf_iterator<char>());
  }
  return o;
}

std::string noSoundReason(const SoundOutputs& o) {
  if (o.driverChosen || o.soundServer) return "";
  const bool noCards = !o.cardListRead || o.cardList.find_first_not_of(" \t\r\n") == std::string::npos ||
                       o.cardList.find("no soundcards") != std::string::npos;
  return noCards ? "no sound: this machine has no sound card and no sound server; the game plays on silently" : "";
}

Audio::Audio(const AudioDef& def, const SoundOutputs& outputs)
    : sampleRate_(def.sampleRate), volume_(std::clamp(def.volume, 0.0, 1.0)) {
  if (const std::string why = noSoundReason(outputs); !why.empty()) {
    note_ = why;
    return;
  }
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
    note_ = std::string("no sound: SDL audio did not start (") + SDL_GetError() + "); the game plays on silently";
    return;
  }
  SDL_AudioSpec want{};
  want.freq = def.sampleRate;
  want.format = AUDIO_F32SYS;
  want.channels = 1;
  want.samples = 512;
  want.callback = &Audio::callback;
  want.userdata = this;
  SDL_AudioSpec have{};
  device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
  if (device_ == 0) {
    note_ = std::string("no sound: no audio device (") + SDL_GetError() + "); the game plays on silently";
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    return;
  }
  sampleRate_ = have.freq;
  SDL_PauseAudioDevice(device_, 0);
}

Audio::~Audio() {
  if (device_ != 0) {
    SDL_CloseAudioDevice(device_);
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
  }
}

void Audio::play(Cue cue) {
  pendingCue_.store(static_cast<int>(cue));
  cuesPlayed_.fetch_add(1);
}

void Audio::setProximity(double closeness) {
  proximity_.store(std::isfinite(closeness) ? std::clamp(closeness, 0.0, 1.0) : 0.0);
}

void Audio::setForceTone(double strain) { forceStrain_.store(std::isfinite(strain) ? std::min(strain, 1.0) : -1.0); }

void Audio::setVolume(double volume) { volume_.store(std::isfinite(volume) ? std::clamp(volume, 0.0, 1.0) : 0.0); }

void Audio::callback(void* self, std::uint8_t* stream, int bytes) {
  static_cast<Audio*>(self)->synthesize(reinterpret_cast<float*>(stream), bytes / static_cast<int>(sizeof(float)));
}

void Audio::synthesize(float* out, int frames) {
  const int requested = pendingCue_.exchange(-1);
  if (requested >= 0) {
    cue_ = requested;
    cueTime_ = 0.0;
  }
  const double volume = volume_.load();
  const double proximity = proximity_.load();
  // The tone: 220 Hz far away rising to 660 Hz at the band, quiet; its level
  // follows the proximity smoothly (no clicks when it starts or stops).
  const double toneFrequency = 220.0 * std::pow(3.0, proximity);
  const double toneTarget = proximity > 0.0 ? 0.08 : 0.0;
  const double dt = 1.0 / sampleRate_;
  // The force tone: quieter than the proximity tone (it sounds all the
  // time); its frequency and level glide with a time constant of 20 ms, so
  // that a force that jumps slides the pitch instead of clicking.
  const double strain = forceStrain_.load();
  const double forceTarget = strain >= 0.0 ? 0.05 : 0.0;
  const double forcePitch = strainPitch(std::max(strain, 0.0));
  const double glide = 1.0 - std::exp(-dt / 0.02);
  for (int i = 0; i < frames; ++i) {
    toneLevel_ += (toneTarget - toneLevel_) * 0.001;
    tonePhase_ = std::fmod(tonePhase_ + kTwoPi * toneFrequency * dt, kTwoPi);
    double sample = toneLevel_ * std::sin(tonePhase_);
    forceLevel_ += (forceTarget - forceLevel_) * glide;
    forceFrequency_ += (forcePitch - forceFrequency_) * glide;
    forcePhase_ = std::fmod(forcePhase_ + kTwoPi * forceFrequency_ * dt, kTwoPi);
    sample += forceLevel_ * std::sin(forcePhase_);
    if (cue_ >= 0) {
      const CueShape& shape = kShapes[cue_];
      for (int n = 0; n < shape.count; ++n) {
        const double t = cueTime_ - shape.notes[n].start;
        if (t < 0.0) continue;
        const double envelope = std::exp(-t * (shape.length < 0.1 ? 150.0 : 6.0));
        sample += 0.3 * envelope * std::sin(kTwoPi * shape.notes[n].frequency * t);
      }
      cueTime_ += dt;
      if (cueTime_ > shape.length) cue_ = -1;
    }
    out[i] = static_cast<float>(std::clamp(sample * volume, -1.0, 1.0));
  }
}

}  // namespace hemiroll::game
