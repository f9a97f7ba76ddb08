#include "wire/protocol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

#include "robot_server/sim_server.h"
#include "sensors/camera/camera.h"
#include "sensors/encoders/encoders.h"
#include "sensors/gnss/gnss.h"
#include "sensors/imu/imu.h"
#include "wire/message_lines.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

ProtocolMessage Parse(const std::string& line) {
  std::string error;
  auto m = ParseLine(line, &error);
  EXPECT_TRUE(m) << line << ": " << error;
  return m.value_or(ProtocolMessage());
}

TEST(Protocol, ParsesUsarsimLinesWhateverTheirSpacingAndCase) {
  const ProtocolMessage m = Parse("init {ClassName USARBot.P2DX}{Name R1}  {Location 4.5,1.9,1.8} {Rotation 0 0 1.57}");
  EXPECT_EQ(m.type, "INIT");
  EXPECT_EQ(*m.Get("classname"), "USARBot.P2DX");
  EXPECT_EQ(*m.Get("Name"), "R1");
  EXPECT_EQ(*m.Numbers("Location"), (std::vector<double>{4.5, 1.9, 1.8}));
  EXPECT_EQ(*m.Numbers("Rotation"), (std::vector<double>{0, 0, 1.57}));  // space-separated too
}

TEST(Protocol, KeepsGroupedPairsAsKeyAndRest) {
  const ProtocolMessage m = Parse("SEN {Time 395.6} {Type Sonar} {Name F1 Range 4.5604} {Name F2 Range 2.4576}");
  ASSERT_EQ(m.fields.size(), 4u);
  EXPECT_EQ(m.fields[2].second, "F1 Range 4.5604");
  EXPECT_EQ(m.fields[3].second, "F2 Range 2.4576");
  EXPECT_DOUBLE_EQ(*m.Number("Time"), 395.6);
}

TEST(Protocol, EveryMessageTypeRoundTrips) {
  std::vector<ProtocolMessage> all;
  all.emplace_back("NFO");
  all.back().Add("Gametype", "BotDeathMatch").Add("Level", "formation").Add("TimeLimit", 420.0);
  all.emplace_back("INIT");
  all.back().Add("ClassName", "USARBot.P2DX").Add("Name", "f1").Add("Location", std::vector<double>{1, -2, 0});
  all.emplace_back("DRIVE");
  all.back().Add("Left", 1.5).Add("Right", -0.25);
  all.emplace_back("DRIVE");
  all.back().Add("LinearVelocity", 0.3).Add("LateralVelocity", 0.1).Add("RotationalVelocity", -0.2);
  all.emplace_back("SEN");
  all.back()
      .Add("Time", 1.0)
      .Add("Type", "RangeScanner")
      .Add("Name", "Scanner1")
      .Add("Resolution", 0.0175)
      .Add("FOV", 3.1416)
      .Add("Range", std::vector<double>{1, 2.5, 8});
  all.emplace_back("SEN");
  all.back()
      .Add("Time", 1.0)
      .Add("Type", "GroundTruth")
      .Add("Name", "GroundTruth")
      .Add("Location", std::vector<double>{1, 2, 0.1})
      .Add("Orientation", std::vector<double>{0, 0, -0.5});
  all.emplace_back("SEN");
  all.back().Add("Type", "IR").Add("Name", "IR0 Range 0.8000").Add("Name", "IR1 Range 0.3000");
  all.emplace_back("STA");
  all.back().Add("Type", "GroundVehicle").Add("Time", 2.0).Add("Battery", "3600");
  all.emplace_back("GETCONF");
  all.back().Add("Type", "Robot");
  all.emplace_back("CONF");
  all.back().Add("Type", "GroundVehicle").Add("SteeringType", "SkidSteered");
  all.emplace_back("GEO");
  all.back().Add("WheelRadius", 0.0975).Add("WheelSeparation", 0.33);
  all.emplace_back("LOG");
  all.back().Add("Text", "transition a -> b: why");
  all.emplace_back("ERR");
  all.back().Add("Message", "unknown command FLY");
  for (const ProtocolMessage& m : all) {
    const std::string line = FormatLine(m);
    ASSERT_EQ(line.substr(line.size() - 2), "\r\n");
    const ProtocolMessage back = Parse(line.substr(0, line.size() - 2));
    EXPECT_EQ(back.type, m.type);
    EXPECT_EQ(back.fields, m.fields) << line;
  }
}

TEST(Protocol, RejectsMalformedLinesSayingWhy) {
  for (const char* bad :
       {"", "   ", "{Name R1}", "DRIVE Left 1", "DRIVE {Left 1", "DRIVE {Left {1}}", "DRIVE {}", "DR-IVE {Left 1}"}) {
    std::string error;
    EXPECT_FALSE(ParseLine(bad, &error)) << bad;
    EXPECT_FALSE(error.empty()) << bad;
  }
  std::string error;
  const auto m = ParseLine("DRIVE {Left fast} {Right 1}", &error);
  ASSERT_TRUE(m);  // the grammar is fine; the value is not a number
  EXPECT_FALSE(m->Number("Left"));
  EXPECT_FALSE(m->Numbers("Left"));
}

TEST(Protocol, LineReaderSplitsEveryLineEndAndLimitsLength) {
  LineReader r(16);
  r.Append("A {x 1}\r\nB\nC\rD\n\rE");
  bool too_long = false;
  std::vector<std::string> lines;
  while (auto line = r.Next(&too_long)) lines.push_back(*line);
  EXPECT_EQ(lines, (std::vector<std::string>{"A {x 1}", "B", "C", "D"}));
  EXPECT_FALSE(too_long);
  r.Append(std::string(40, 'x'));
  EXPECT_FALSE(r.Next(&too_long));
  EXPECT_TRUE(too_long);
}

// Lines arrive in pieces of any size, in any number: each comes out whole, once, in order, and
// the reader holds no more than what is not yet taken.
TEST(Protocol, LineReaderJoinsPiecesAndKeepsOnlyWhatIsPending) {
  LineReader r(64);
  std::string stream;
  for (int i = 0; i < 5000; ++i) stream += "DRIVE {Left " + std::to_string(i) + "} {Right 0}\r\n";
  bool too_long = false;
  int next = 0;
  for (std::size_t at = 0; at < stream.size(); at += 7) {  // 7-byte pieces split lines and CR LF
    r.Append(std::string_view(stream).substr(at, 7));
    while (auto line = r.Next(&too_long)) ASSERT_EQ(*line, "DRIVE {Left " + std::to_string(next++) + "} {Right 0}");
    ASSERT_FALSE(too_long);
    ASSERT_LT(r.Pending(), 64u);
  }
  EXPECT_EQ(next, 5000);
  r.Append("half a li");
  EXPECT_FALSE(r.Next(&too_long));
  r.Append("ne\n");
  EXPECT_EQ(r.Next(&too_long).value_or(""), "half a line");
  EXPECT_EQ(r.Pending(), 0u);
}

// A message handed to a client as a MSG line reads back as the same message on the agent's side.
TEST(MessageLines, MsgLineRoundTripsThroughTheProtocol) {
  Message m;
  m.from = 3;
  m.delivery = Delivery::kUnicast;
  m.time_sent = 12.0001;
  m.time_received = 12.004321;
  m.hops = 2;
  m.payload = {0x00, 0xff, 0x7b, 0x7d, 0x0a};  // braces and a line end: hex keeps them out of the line
  const std::string line = FormatLine(MsgLine(m, "m3"));
  std::string error;
  const auto parsed = ParseLine(line.substr(0, line.size() - 2), &error);
  ASSERT_TRUE(parsed) << error;
  const auto back = ParseMsgLine(*parsed, NodeId{3}, 7, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->payload, m.payload);
  EXPECT_EQ(back->to, 7u);
  EXPECT_EQ(back->hops, 2);
  EXPECT_NEAR(back->time_received, m.time_received, 1e-6);
  EXPECT_EQ(ToHex(m.payload), "00ff7b7d0a");
  EXPECT_FALSE(FromHex("0g"));
  EXPECT_FALSE(FromHex("abc"));
  ProtocolMessage broken("MSG");
  broken.Add("From", "m3").Add("Delivery", "sideways");
  EXPECT_FALSE(ParseMsgLine(broken, NodeId{3}, 7, &error));
  EXPECT_NE(error.find("MSG needs"), std::string::npos);
}

}  // namespace
}  // namespace sanet::wire

namespace sanet::wire {
namespace {

// ERR text never holds a brace, and still reads: a field's name quoted, a field with its value in
// parentheses, lone braces as quotes.
TEST(MessageLines, ErrTextHasNoBraces) {
  EXPECT_EQ(robot_server::WithoutBraces("DRIVE needs {Left} and {Right}"), "DRIVE needs 'Left' and 'Right'");
  EXPECT_EQ(robot_server::WithoutBraces("INIT {ClassName c} {Name x} adds one"),
            "INIT (ClassName c) (Name x) adds one");
  EXPECT_EQ(robot_server::WithoutBraces("unclosed {a {b} }{ }").find_first_of("{}"), std::string::npos);
  EXPECT_EQ(robot_server::WithoutBraces("a lone { here"), "a lone ' here");
}

// Counts a client gives are whole numbers in range, never converted out of range (the fuzzer
// found RECV {Bytes 3.9e98}, which also asked the server for that many bytes).
TEST(MessageLines, RecvAndMsgRefuseCountsOutOfRange) {
  std::string error;
  const auto recv = [&](const std::string& tail) {
    const auto m = ParseLine("RECV {From f1} {Delivery unicast} {TimeSent 1} {TimeReceived 2} " + tail, &error);
    return ParseRecvLine(*m, NodeId{1}, 2, &error);
  };
  ASSERT_TRUE(recv("{Bytes 41} {Hops 1}")) << error;
  EXPECT_EQ(recv("{Bytes 41}")->bytes, 41u);
  for (const char* bad : {"{Bytes 3.9e98}", "{Bytes 65508}", "{Bytes -1}", "{Bytes 2.5}", "{Bytes 4} {Hops 1e12}",
                          "{Bytes 4} {Hops -3}"}) {
    EXPECT_FALSE(recv(bad)) << bad;
    EXPECT_NE(error.find("up to 65507"), std::string::npos) << error;
  }
  const auto msg =
      ParseLine("MSG {From m3} {Delivery unicast} {TimeSent 1} {TimeReceived 2} {Hops 1e300} {Data 00}", &error);
  EXPECT_FALSE(ParseMsgLine(*msg, NodeId{3}, 1, &error));
  ProtocolMessage counts{"STATS"};
  counts.Add("Steps", "12").Add("Big", "1e30").Add("Part", "0.5");
  EXPECT_EQ(counts.Count("Steps", 100).value_or(0), 12u);
  EXPECT_FALSE(counts.Count("Steps", 10));
  EXPECT_FALSE(counts.Count("Big", std::uint64_t{1} << 53));
  EXPECT_FALSE(counts.Count("Part", 10));
}

}  // namespace
}  // namespace sanet::wire

namespace sanet::wire {
namespace {

// A reading written as its SEN line, sent as text, parsed and read back.
SensorReading ThroughTheLine(const std::string& kind, const SensorReading& reading, const std::any& settings) {
  const SensorLines* lines = LinesOf(kind);
  EXPECT_NE(lines, nullptr) << kind;
  LineContext context;
  context.time = 2.5;
  const std::vector<ProtocolMessage> written = lines->Write(kind, reading, context);
  EXPECT_EQ(written.size(), 1u);
  std::string error;
  const auto parsed = ParseLine(FormatLine(written.at(0)), &error);
  EXPECT_TRUE(parsed) << error;
  EXPECT_TRUE(lines->IsFrom(*parsed, kind));
  const auto back = lines->Read(*parsed, settings, context);
  EXPECT_TRUE(back);
  return *back;
}

TEST(SensorLines, EncodersGoAsTicksOfAMilliradian) {
  sensors::EncodersSettings settings;
  settings.names = {"wheel_l", "wheel_r"};
  const JointStatesReading sent{{"wheel_l", "wheel_r"}, {12.3456789, -0.5}, {4, -4}};
  const std::string line = FormatLine(LinesOf("encoders")->Write("encoders", sent, LineContext{}).at(0));
  EXPECT_NE(line.find("{Type Encoder} {Name ECLeft Tick 12346} {Name ECRight Tick -500}"), std::string::npos) << line;
  const auto back = std::get<JointStatesReading>(ThroughTheLine("encoders", sent, settings));
  EXPECT_EQ(back.names, settings.names);
  ASSERT_EQ(back.angles.size(), 2u);
  EXPECT_NEAR(back.angles[0], 12.3456789, 5e-4);
  EXPECT_NEAR(back.angles[1], -0.5, 5e-4);
}

TEST(SensorLines, AnImuReadingRoundTripsToSixDecimals) {
  sensors::ImuSettings settings;
  settings.rate = 200, settings.gyroscope_noise_density = 1e-3;
  ImuReading sent;
  sent.angular_velocity = {0.000123, -0.2, 0.75};
  sent.linear_acceleration = {1.5, -0.001234, 9.81};
  sent.orientation = Quaternion{0, 0, 0.6, 0.8};
  const auto back = std::get<ImuReading>(ThroughTheLine("imu", sent, settings));
  EXPECT_NEAR(back.angular_velocity.x, 0.000123, 1e-6);
  EXPECT_NEAR(back.angular_velocity.z, 0.75, 1e-6);
  EXPECT_NEAR(back.linear_acceleration.y, -0.001234, 1e-6);
  EXPECT_NEAR(back.linear_acceleration.z, 9.81, 1e-6);
  ASSERT_TRUE(back.orientation);
  EXPECT_NEAR(back.orientation->z, 0.6, 1e-6);
  EXPECT_NEAR(back.angular_velocity_covariance[0], 1e-6 * 200, 1e-12) << "the noise's variance from the scenario";
  sent.orientation.reset();
  EXPECT_EQ(std::get<ImuReading>(ThroughTheLine("imu", sent, settings)).orientation_covariance[0], -1);
}

TEST(SensorLines, AFixGoesAsUsarsimsDegreesAndMinutesAndNoFixAsFixZero) {
  sensors::GnssSettings settings;
  settings.horizontal_noise = 2, settings.vertical_noise = 3;
  FixReading sent;
  sent.status = FixReading::kFix;
  sent.latitude = -33.8567844, sent.longitude = 151.2152967, sent.altitude = 42.25;
  const std::string line = FormatLine(LinesOf("gnss")->Write("gnss", sent, LineContext{}).at(0));
  EXPECT_NE(line.find("{Type GPS} {Name GPS} {Latitude 33,51.407064,S} {Longitude 151,12.917802,E} {Fix 1}"),
            std::string::npos)
      << line;
  const auto back = std::get<FixReading>(ThroughTheLine("gnss", sent, settings));
  EXPECT_EQ(back.status, FixReading::kFix);
  EXPECT_NEAR(back.latitude, sent.latitude, 1e-7);  // a millionth of a minute: 2 mm
  EXPECT_NEAR(back.longitude, sent.longitude, 1e-7);
  EXPECT_NEAR(back.altitude, 42.25, 1e-6);
  EXPECT_EQ(back.position_covariance[0], 4);
  EXPECT_EQ(back.position_covariance[8], 9);
  sent.latitude = 1 - 1e-12;  // minutes that round up to the next degree
  EXPECT_NE(FormatLine(LinesOf("gnss")->Write("gnss", sent, LineContext{}).at(0)).find("{Latitude 1,0.000000,N}"),
            std::string::npos);
  FixReading none;
  none.status = FixReading::kNoFix;
  const std::string lost = FormatLine(LinesOf("gnss")->Write("gnss", none, LineContext{}).at(0));
  EXPECT_NE(lost.find("{Name GPS} {Fix 0} {Satellites 0}"), std::string::npos) << lost;
  const auto nothing = std::get<FixReading>(ThroughTheLine("gnss", none, settings));
  EXPECT_EQ(nothing.status, FixReading::kNoFix);
  EXPECT_TRUE(std::isnan(nothing.latitude));
}

TEST(SensorLines, APictureGoesAsPngInBase64AndComesBackPixelForPixel) {
  ImageReading sent;
  sent.width = 64, sent.height = 48, sent.encoding = "rgb8";
  for (int i = 0; i < 64 * 48 * 3; ++i) sent.data.push_back(static_cast<std::uint8_t>((i * 37 + i / 191) % 256));
  const std::string line = FormatLine(LinesOf("camera")->Write("camera", sent, LineContext{}).at(0));
  EXPECT_NE(line.find("{Type Camera} {Name Camera} {Width 64} {Height 48} {Encoding png} {Data iVBORw0KGgo"),
            std::string::npos)
      << line.substr(0, 120);
  const auto back = std::get<ImageReading>(ThroughTheLine("camera", sent, sensors::CameraSettings{}));
  EXPECT_EQ((std::tuple{back.width, back.height, back.encoding}), (std::tuple{64, 48, std::string("rgb8")}));
  EXPECT_EQ(back.data, sent.data);
  ImageReading large = sent;  // noise does not compress: past the line's 256 KiB
  large.width = 400, large.height = 300, large.data.resize(400 * 300 * 3);
  std::mt19937 noise(7);
  for (std::uint8_t& c : large.data) c = static_cast<std::uint8_t>(noise());
  EXPECT_TRUE(LinesOf("camera")->Write("camera", large, LineContext{}).empty());
  for (const char* fields :
       {"{Width 64} {Height 48} {Encoding png} {Data !!!!}", "{Width 64} {Height 48} {Encoding jpeg} {Data aaaa}",
        "{Width 65} {Height 48} {Encoding png} {Data iVBORw0KGgo=}", "{Width 64} {Height 48} {Encoding png}"}) {
    std::string error;
    const auto parsed = ParseLine(std::string("SEN {Type Camera} {Name Camera} ") + fields, &error);
    ASSERT_TRUE(parsed) << error;
    EXPECT_FALSE(LinesOf("camera")->Read(*parsed, sensors::CameraSettings{}, LineContext{})) << fields;
  }
}

TEST(SensorLines, AMalformedFixIsNoReading) {
  for (const char* fields :
       {"{Latitude -47,40.1,N} {Longitude 1,0,E}", "{Latitude 47,60,N} {Longitude 1,0,E}",
        "{Latitude nan,0,N} {Longitude 1,0,E}", "{Latitude 91,0,N} {Longitude 1,0,E}",
        "{Latitude 47,1,N} {Longitude 181,0,W}", "{Latitude 47,1,X} {Longitude 1,0,E}",
        "{Latitude 47,1,N} {Longitude 1,0,E extra}", "{Latitude 47.5,1,N} {Longitude 1,0,E}", "{Longitude 1,0,E}"}) {
    std::string error;
    const auto line = ParseLine(std::string("SEN {Type GPS} {Name GPS} ") + fields + " {Fix 1}", &error);
    ASSERT_TRUE(line) << error;
    EXPECT_FALSE(LinesOf("gnss")->Read(*line, sensors::GnssSettings{}, LineContext{})) << fields;
  }
}

}  // namespace
}  // namespace sanet::wire
