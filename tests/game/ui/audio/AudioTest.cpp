#include "game/ui/audio/Audio.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <vector>

namespace hemiroll::game {
namespace {

// Synthesis is called directly: on SDL's dummy driver the device thread may
// also call it, so each test here uses its own Audio on a driver that cannot
// open (no thread) unless it tests the device itself.
class AudioTest : public ::testing::Test {
 protected:
  void SetUp() override { setenv("SDL_AUDIODRIVER", "no-such-driver", 1); }
};

double peak(const std::vector<float>& v) {
  double p = 0.0;
  for (float s : v) p = std::max(p, std::abs(static_cast<double>(s)));
  return p;
}

int zeroCrossings(const std::vector<float>& v) {
  int n = 0;
  for (std::size_t i = 1; i < v.size(); ++i) n += (v[i - 1] < 0.0f) != (v[i] < 0.0f);
  return n;
}

// No card and no sound server: SDL is not asked (its ALSA backend would
// print the ALSA library's errors to the terminal); the note says why in
// one sentence. A chosen driver, a server or a card: SDL is asked.
TEST_F(AudioTest, NoSoundCardIsSaidOnceInOurWordsWithoutAskingSdl) {
  SoundOutputs none;
  none.cardListRead = true;
  none.cardList = "--- no soundcards ---\n";
  EXPECT_NE(noSoundReason(none).find("no sound card"), std::string::npos);
  SoundOutputs unreadable;  // no /proc/asound at all (a container)
  EXPECT_NE(noSoundReason(unreadable), "");
  Audio silent(AudioDef{}, none);
  EXPECT_FALSE(silent.available());
  EXPECT_EQ(silent.note(), noSoundReason(none));

  SoundOutputs card = none;
  card.cardList = " 0 [PCH            ]: HDA-Intel - HDA Intel PCH\n";
  EXPECT_EQ(noSoundReason(card), "");
  SoundOutputs server = none;
  server.soundServer = true;
  EXPECT_EQ(noSoundReason(server), "");
  SoundOutputs chosen = none;
  chosen.driverChosen = true;
  EXPECT_EQ(noSoundReason(chosen), "");
}

TEST_F(AudioTest, AMissingDriverMeansSilenceWithANoteNeverAFailure) {
  Audio audio;
  EXPECT_FALSE(audio.available());
  EXPECT_NE(audio.note().find("no sound"), std::string::npos) << audio.note();
  audio.play(Cue::Success);  // no-ops that must not crash
  audio.setProximity(0.5);
  EXPECT_EQ(audio.cuesPlayed(), 1u);
}

TEST_F(AudioTest, SilentWithoutCueOrToneAndBoundedWithOne) {
  Audio audio;
  std::vector<float> buffer(4800);
  audio.synthesize(buffer.data(), static_cast<int>(buffer.size()));
  EXPECT_EQ(peak(buffer), 0.0);
  audio.play(Cue::Success);
  audio.synthesize(buffer.data(), static_cast<int>(buffer.size()));
  EXPECT_GT(peak(buffer), 0.05);  // the chime is audible (0.3 per note before volume 0.6)
  EXPECT_LE(peak(buffer), 1.0);
}

TEST_F(AudioTest, VolumeZeroSilencesCues) {
  Audio audio;
  audio.setVolume(0.0);
  audio.play(Cue::Failure);
  std::vector<float> buffer(4800);
  audio.synthesize(buffer.data(), static_cast<int>(buffer.size()));
  EXPECT_EQ(peak(buffer), 0.0);
  audio.setVolume(std::nan(""));  // bad input: silence, not NaN samples
  audio.play(Cue::Failure);
  audio.synthesize(buffer.data(), static_cast<int>(buffer.size()));
  EXPECT_EQ(peak(buffer), 0.0);
}

TEST_F(AudioTest, TheToneRisesAsTheStateNearsTolerance) {
  // 2 s per setting: the tone's level settles within ~0.1 s (time constant
  // 1000 samples), so the last second is the steady tone.
  auto crossings = [](double closeness) {
    Audio audio;
    audio.setProximity(closeness);
    std::vector<float> buffer(96000);
    audio.synthesize(buffer.data(), static_cast<int>(buffer.size()));
    return zeroCrossings(std::vector<float>(buffer.begin() + 48000, buffer.end()));
  };
  const int far = crossings(0.1), near = crossings(1.0);
  // 220 * 3^0.1 = 245 Hz -> ~490 crossings/s; 660 Hz -> ~1320 (+-2 for phase).
  EXPECT_NEAR(far, 2 * 220.0 * std::pow(3.0, 0.1), 4);
  EXPECT_NEAR(near, 2 * 660.0, 4);
}

// The force tone's pitch follows the strain: 180 Hz at none, 720 Hz at
// full (strainPitch), measured by zero crossings over the steady second.
TEST_F(AudioTest, TheForceTonesPitchFollowsTheStrain) {
  auto crossings = [](double strain) {
    Audio audio;
    audio.setForceTone(strain);
    std::vector<float> buffer(96000);
    audio.synthesize(buffer.data(), static_cast<int>(buffer.size()));
    return zeroCrossings(std::vector<float>(buffer.begin() + 48000, buffer.end()));
  };
  EXPECT_NEAR(crossings(0.0), 2 * 180.0, 4);
  EXPECT_NEAR(crossings(0.5), 2 * 360.0, 4);
  EXPECT_NEAR(crossings(1.0), 2 * 720.0, 4);
  EXPECT_NEAR(crossings(5.0), 2 * 720.0, 4);  // clamped
}

// No clicks: a force that jumps from none to full, and the tone switched
// off, change the waveform by no more than its own slope allows. A sine of
// amplitude A at f moves at most 2 pi f A / rate per sample: 720 Hz at the
// tone's 0.05 x volume 0.6 at 48 kHz is 0.0028; a click (a step) would be
// up to the whole amplitude, 0.03.
TEST_F(AudioTest, TheForceToneGlidesWithoutClicks) {
  Audio audio;
  std::vector<float> buffer(48000);
  audio.setForceTone(0.0);
  audio.synthesize(buffer.data(), 24000);
  audio.setForceTone(1.0);  // a jump of the force
  audio.synthesize(buffer.data() + 24000, 12000);
  audio.setForceTone(-1.0);  // switched off
  audio.synthesize(buffer.data() + 36000, 12000);
  double largest = 0.0;
  for (std::size_t i = 1; i < buffer.size(); ++i)
    largest = std::max(largest, std::abs(static_cast<double>(buffer[i]) - buffer[i - 1]));
  EXPECT_LT(largest, 2 * M_PI * 720.0 * 0.05 * 0.6 / 48000.0 * 1.05);
  EXPECT_GT(peak(std::vector<float>(buffer.begin() + 30000, buffer.begin() + 36000)), 0.02);  // it sounded
  EXPECT_LT(peak(std::vector<float>(buffer.end() - 2000, buffer.end())), 1e-4);             // and stopped
}

TEST(AudioDeviceTest, OpensOnSdlsDummyDriver) {
  setenv("SDL_AUDIODRIVER", "dummy", 1);
  Audio audio;
  EXPECT_TRUE(audio.available()) << audio.note();
  audio.play(Cue::Engage);
  EXPECT_EQ(audio.cuesPlayed(), 1u);
}

}  // namespace
}  // namespace hemiroll::game
