#pragma once
// The game's sounds, synthesized (no asset files to lose): a success chime
// (rising triad, like the paper's success sound), a failure tone (falling),
// engage/disengage clicks, and a gentle tone whose pitch rises as the state
// nears tolerance; and the force tone (issue 26), quieter, whose pitch
// follows the coupling force for a player who cannot feel it. Played through SDL audio; the UI thread only sets atomics
// and SDL's audio thread synthesizes, so the game never waits for sound.
//
// Audio failure never stops the game: without a device (no sound card, a
// broken driver) every call is a no-op and note() says why. Tests use SDL's
// dummy driver (SDL_AUDIODRIVER=dummy).

#include <atomic>
#include <cstdint>
#include <string>

namespace hemiroll::game {

enum class Cue : std::uint8_t { Success, Failure, Engage, Disengage };

// What the machine offers for sound, looked at before SDL is asked: on a
// machine without a sound card SDL's ALSA backend lets the ALSA library
// print a dozen errors of its own to the terminal.
struct SoundOutputs {
  bool driverChosen = false;     // SDL_AUDIODRIVER is set: SDL is asked as told
  bool soundServer = false;      // a PulseAudio or PipeWire socket, or PULSE_SERVER
  bool cardListRead = false;     // /proc/asound/cards could be read
  std::string cardList;          // its text
  static SoundOutputs probe();   // this machine, now
};
// Why there can be no sound, in a player's words ("" when SDL should be asked).
std::string noSoundReason(const SoundOutputs& outputs);

struct AudioDef {
  double volume = 0.6;       // [0, 1]
  int sampleRate = 48000;    // [Hz]
};

class Audio {
 public:
  explicit Audio(const AudioDef& def = {}, const SoundOutputs& outputs = SoundOutputs::probe());
  ~Audio();
  Audio(const Audio&) = delete;
  Audio& operator=(const Audio&) = delete;

  bool available() const { return device_ != 0; }
  const std::string& note() const { return note_; }  // why there is no sound ("" when there is)

  void play(Cue cue);
  // 0 = silent; (0, 1]: the tone's closeness to tolerance (1 = inside).
  void setProximity(double closeness);
  // The force tone: its pitch for a strain in [0, 1] (ForceCues.h's
  // strainPitch: 180 Hz to 720 Hz); a negative strain (or NaN) silences it.
  // Pitch and level glide (a few tens of ms), so that a jumping force never
  // clicks.
  void setForceTone(double strain);
  void setVolume(double volume);
  double volume() const { return volume_.load(); }
  // Cues requested so far (tests check that play events happen).
  std::uint64_t cuesPlayed() const { return cuesPlayed_.load(); }

  // Fills `frames` mono float samples (what SDL's callback does); public so
  // that the synthesis is tested without a device.
  void synthesize(float* out, int frames);

 private:
  static void callback(void* self, std::uint8_t* stream, int bytes);

  std::uint32_t device_ = 0;
  std::string note_;
  double sampleRate_;
  std::atomic<double> volume_;
  std::atomic<double> proximity_{0.0};
  std::atomic<double> forceStrain_{-1.0};
  std::atomic<int> pendingCue_{-1};
  std::atomic<std::uint64_t> cuesPlayed_{0};
  // Audio thread only.
  int cue_ = -1;
  double cueTime_ = 0.0;
  double tonePhase_ = 0.0;
  double toneLevel_ = 0.0;
  double forcePhase_ = 0.0;
  double forceLevel_ = 0.0;
  double forceFrequency_ = 180.0;  // [Hz], gliding to the strain's pitch
};

}  // namespace hemiroll::game
