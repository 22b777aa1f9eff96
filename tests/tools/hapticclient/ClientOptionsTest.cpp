#include "tools/hapticclient/ClientOptions.h"

#include <gtest/gtest.h>

namespace hemiroll::hapticclient {
namespace {

TEST(ClientOptionsTest, DefaultsAndEveryOption) {
  EXPECT_EQ(parseClientOptions({}).options.port, 47110);
  const ParsedOptions p = parseClientOptions({"--host", "127.0.0.2", "--port", "5000", "--duration", "2.5", "--rate",
                                              "500", "--hand-mass", "0.2", "--hand-stiffness", "400",
                                              "--hand-damping", "12", "--centre", "0.01,-0.02,0.04",
                                              "--circle-radius", "0.005", "--circle-frequency", "2",
                                              "--realtime-priority", "70"});
  ASSERT_EQ(p.error, "");
  const ClientOptions& o = p.options;
  EXPECT_EQ(o.host, "127.0.0.2");
  EXPECT_EQ(o.port, 5000);
  EXPECT_EQ(o.duration, 2.5);
  EXPECT_EQ(o.rate, 500.0);
  EXPECT_EQ(o.hand.mass, 0.2);
  EXPECT_EQ(o.hand.stiffness, 400.0);
  EXPECT_EQ(o.hand.damping, 12.0);
  EXPECT_EQ(o.centre, (std::array<double, 3>{0.01, -0.02, 0.04}));
  EXPECT_EQ(o.circleRadius, 0.005);
  EXPECT_EQ(o.circleFrequency, 2.0);
  EXPECT_EQ(o.realtimePriority, 70);
  EXPECT_TRUE(parseClientOptions({"--help"}).options.help);
  // Without --centre the hand starts on a default level's mass point, where
  // the coupling engages (at the origin it stayed armed all trial).
  EXPECT_EQ(parseClientOptions({}).options.centre, (std::array<double, 3>{0.0, 0.0, 0.04}));
}

TEST(ClientOptionsTest, TheSimulatedDeviceAndItsFaults) {
  const ParsedOptions p = parseClientOptions({"--peak-force", "3.3", "--handle-mass", "0.05", "--friction", "0.02",
                                              "--resolution", "0.000055", "--jitter", "0.0005", "--loss", "0.01",
                                              "--reorder", "0.02", "--seed", "9", "--pause-at", "1", "--pause-for",
                                              "0.05", "--exit-at", "2", "--fault-at", "1.5", "--step", "0.002",
                                              "--step-period", "0.1", "--passive"});
  ASSERT_EQ(p.error, "");
  const ClientOptions& o = p.options;
  EXPECT_EQ(o.peakForce, 3.3);
  EXPECT_EQ(o.handleMass, 0.05);
  EXPECT_EQ(o.friction, 0.02);
  EXPECT_EQ(o.resolution, 0.000055);
  EXPECT_EQ(o.jitter, 0.0005);
  EXPECT_EQ(o.loss, 0.01);
  EXPECT_EQ(o.reorder, 0.02);
  EXPECT_EQ(o.seed, 9u);
  EXPECT_EQ(o.pauseAt, 1.0);
  EXPECT_EQ(o.pauseFor, 0.05);
  EXPECT_EQ(o.exitAt, 2.0);
  EXPECT_EQ(o.faultAt, 1.5);
  EXPECT_EQ(o.step, 0.002);
  EXPECT_EQ(o.stepPeriod, 0.1);
  EXPECT_EQ(o.hand.stiffness, 0.0);
  EXPECT_EQ(o.hand.damping, 0.0);
  EXPECT_EQ(parseClientOptions({"--loss", "1.5"}).error, "flag --loss needs a probability in 0..1, got '1.5'");
}

TEST(ClientOptionsTest, BadValuesNameTheFlagAndTheValue) {
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const Case cases[] = {
      {{"--port", "70000"}, "flag --port needs an integer port in 1..65535, got '70000'"},
      {{"--port", "12.5"}, "flag --port needs an integer port in 1..65535, got '12.5'"},
      {{"--duration", "-1"}, "flag --duration needs a positive number of seconds, at most 1e6, got '-1'"},
      {{"--duration", "1e300"}, "flag --duration needs a positive number of seconds, at most 1e6, got '1e300'"},
      {{"--rate", "abc"}, "flag --rate needs a rate in 1..10000 Hz, got 'abc'"},
      {{"--hand-mass", "0"}, "flag --hand-mass needs a positive mass in kg, got '0'"},
      {{"--hand-stiffness", "nan"}, "flag --hand-stiffness needs a stiffness >= 0 in N/m, got 'nan'"},
      {{"--centre", "1,2"}, "flag --centre needs three numbers x,y,z in metres, got '1,2'"},
      {{"--centre", "1,2,3,4"}, "flag --centre needs three numbers x,y,z in metres, got '1,2,3,4'"},
      {{"--realtime-priority", "100"}, "flag --realtime-priority needs an integer priority in 0..99, got '100'"},
      {{"--port"}, "flag --port needs a value"},
      {{"--speed", "3"}, "unknown flag '--speed'"},
      {{"stray"}, "unexpected argument 'stray'"},
  };
  for (const Case& c : cases) EXPECT_EQ(parseClientOptions(c.args).error, c.expected);
}

}  // namespace
}  // namespace hemiroll::hapticclient
