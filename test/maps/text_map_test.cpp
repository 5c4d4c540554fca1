#include "doorplate_localization/maps/text_map.h"

#include <gtest/gtest.h>

#include "map_test_util.h"

namespace doorplate_localization {
namespace {

using test::Contains;
using test::ErrorOf;

TextLandmark Plate(const std::string& text, double x, double y, const std::string& wall) {
  TextLandmark l;
  l.text = text;
  l.pose = {x, y, -M_PI / 2};
  l.wall = wall;
  return l;
}

const char kValid[] =
    "format_version: 1\n"
    "frame_id: map\n"
    "occupancy_map: ward.yaml\n"
    "landmarks:\n"
    "  - {index: 1, text: \"214\", x_m: 6.0, y_m: 2.2, yaw_rad: -1.5708, wall: north}\n"
    "  - {index: 0, text: \"212\", x_m: 2.0, y_m: 2.2, yaw_rad: -1.5708, wall: north, observations: 3}\n"
    "adjacent:\n"
    "  - {from: 0, to: 1, distance_m: 4.0, source: odometry}\n";

TEST(ParseTextMap, OrdersLandmarksByIndexAndKeepsDefaults) {
  const TextMap map = ParseTextMap(kValid, "m.yaml");
  ASSERT_EQ(map.landmarks.size(), 2u);
  EXPECT_EQ(map.landmarks[0].text, "212");
  EXPECT_EQ(map.landmarks[0].observations, 3);
  EXPECT_EQ(map.landmarks[1].text, "214");
  EXPECT_DOUBLE_EQ(map.landmarks[1].height_m, 1.6);
  EXPECT_EQ(map.occupancy_map, "ward.yaml");
  ASSERT_EQ(map.adjacent.size(), 1u);
  EXPECT_EQ(map.adjacent[0].source, "odometry");
}

TEST(SaveTextMap, SaveThenLoadGivesTheSameMap) {
  test::TempDir dir;
  TextMap map;
  map.occupancy_map = "ward.yaml";
  map.room_pattern = "[0-9]{4}|A\"QUOTED\"\\d";  // quotes and a backslash to escape; fits both texts
  map.landmarks = {Plate("0210", 2.1, 2.2, "north"), Plate("A \"quoted\": 7", 0.1 + 0.2, -1e-7, "")};
  map.landmarks[1].height_m = 1.55;
  map.landmarks[1].observations = 12;
  map.landmarks[1].position_stddev_m = 0.03;
  map.adjacent = {{0, 1, 3.3, "odometry"}};
  SaveTextMap(map, dir.Path("t.yaml"));
  EXPECT_EQ(dir.List(), std::vector<std::string>{"t.yaml"});
  const TextMap back = LoadTextMap(dir.Path("t.yaml"));
  ASSERT_EQ(back.landmarks.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const TextLandmark& a = map.landmarks[i];
    const TextLandmark& b = back.landmarks[i];
    EXPECT_EQ(b.text, a.text);
    EXPECT_NEAR(b.pose.x_m, a.pose.x_m, 1e-9);  // numbers are written rounded to 1e-9
    EXPECT_NEAR(b.pose.y_m, a.pose.y_m, 1e-9);
    EXPECT_NEAR(b.pose.theta_rad, a.pose.theta_rad, 1e-9);
    EXPECT_EQ(b.height_m, a.height_m);
    EXPECT_EQ(b.wall, a.wall);
    EXPECT_EQ(b.observations, a.observations);
    EXPECT_EQ(b.position_stddev_m, a.position_stddev_m);
  }
  EXPECT_EQ(back.occupancy_map, "ward.yaml");
  EXPECT_EQ(back.room_pattern, map.room_pattern);
  ASSERT_EQ(back.adjacent.size(), 1u);
  EXPECT_EQ(back.adjacent[0].to, 1);
  EXPECT_EQ(back.adjacent[0].distance_m, 3.3);
  EXPECT_EQ(back.adjacent[0].source, "odometry");
}

TEST(TextMapToYaml, WritesNumbersRoundedToANanometreWithoutArithmeticNoise) {
  TextMap map;
  map.landmarks = {Plate("1", 0.1 + 0.2, -1e-12, "w")};
  const std::string yaml = TextMapToYaml(map);
  EXPECT_TRUE(Contains(yaml, "x_m: 0.3, y_m: 0, yaw_rad: -1.570796327,")) << yaml;
}

TEST(TextMapToYaml, AnEmptyMapReadsBackEmpty) {
  const TextMap back = ParseTextMap(TextMapToYaml(TextMap{}), "mem");
  EXPECT_TRUE(back.landmarks.empty());
  EXPECT_TRUE(back.adjacent.empty());
  EXPECT_EQ(back.frame_id, "map");
}

TEST(SaveTextMap, RefusesAMapThatWouldNotLoad) {
  test::TempDir dir;
  TextMap map;
  map.landmarks = {Plate("", 0, 0, "w")};
  const std::string error = ErrorOf<TextMapError>([&] { SaveTextMap(map, dir.Path("t.yaml")); });
  EXPECT_TRUE(Contains(error, dir.Path("t.yaml") + ": landmarks[0].text: must not be empty")) << error;
  EXPECT_TRUE(dir.List().empty());
}

TEST(TextMap, RepeatedRoomNumbersAreAllowedAndFindReturnsEveryOne) {
  TextMap map;
  map.landmarks = {Plate("220", 26, 2.2, "north"), Plate("219", 22, 0, "south"), Plate("220", 26, 0, "south")};
  const TextMap back = ParseTextMap(TextMapToYaml(map), "mem");
  EXPECT_EQ(back.Find("220"), (std::vector<int>{0, 2}));
  EXPECT_EQ(back.Find("219"), std::vector<int>{1});
  EXPECT_TRUE(back.Find("221").empty());
  EXPECT_EQ(back.Texts(), (std::vector<std::string>{"219", "220"}));
}

TEST(TextMap, FindAndTextsCompareRoomsInCanonicalForm) {
  TextMap map;
  map.landmarks = {Plate("E14-295", 0, 0, "n"), Plate("e14 295", 4, 0, "s"), Plate("32-069T", 8, 0, "n"),
                   Plate("32-076", 12, 0, "n"), Plate("312A", 16, 0, "n")};
  EXPECT_EQ(map.Find("E14295"), (std::vector<int>{0, 1}));
  EXPECT_EQ(map.Find("e14-295"), (std::vector<int>{0, 1}));
  EXPECT_EQ(map.Find("32069T"), std::vector<int>{2});
  EXPECT_EQ(map.Find("32-076"), std::vector<int>{3});  // not 32-069T
  EXPECT_TRUE(map.Find("312B").empty());               // a look-alike is another room
  EXPECT_TRUE(map.Find("-").empty());
  EXPECT_EQ(map.Texts(), (std::vector<std::string>{"312A", "32-069T", "32-076", "E14-295"}));
}

TEST(SaveTextMap, TheRoomPatternAndPrintedTextsRoundTrip) {
  test::TempDir dir;
  TextMap map;
  map.room_pattern = "[A-Z]{0,2}[0-9]{1,6}[A-Z]{0,2}|WC";
  map.landmarks = {Plate("76\xC2\xB7" "100SC", 0, 0, "n"), Plate("B/1404", 4, 0, "n"), Plate("39.A", 8, 0, "n"),
                   Plate("WC", 12, 0, "n")};
  SaveTextMap(map, dir.Path("t.yaml"));
  const TextMap back = LoadTextMap(dir.Path("t.yaml"));
  EXPECT_EQ(back.room_pattern, map.room_pattern);
  ASSERT_EQ(back.landmarks.size(), 4u);
  EXPECT_EQ(back.landmarks[0].text, "76\xC2\xB7" "100SC");
  EXPECT_EQ(back.landmarks[1].text, "B/1404");
  EXPECT_EQ(back.landmarks[2].text, "39.A");
  EXPECT_EQ(back.landmarks[3].text, "WC");
}

TEST(ParseTextMap, WithoutARoomPatternTheDefaultGrammarApplies) {
  const TextMap map = ParseTextMap(kValid, "m.yaml");
  EXPECT_EQ(map.room_pattern, kDefaultRoomPattern);
}

TEST(ParseTextMap, ABuildingPatternDecidesWhichTextsAreRooms) {
  const std::string with_wc = std::string(kValid).replace(std::string(kValid).find("text: \"214\""), 11, "text: \"WC\"");
  const std::string error = ErrorOf<TextMapError>([&] { ParseTextMap(with_wc, "w.yaml"); });
  EXPECT_TRUE(Contains(error, "w.yaml: landmarks[0].text: 'WC'")) << error;
  const TextMap map = ParseTextMap("room_pattern: \"[0-9]{3}|WC\"\n" + with_wc, "w.yaml");
  EXPECT_EQ(map.landmarks[1].text, "WC");
  const std::string short_error =
      ErrorOf<TextMapError>([&] { ParseTextMap("room_pattern: \"[0-9]{4}\"\n" + std::string(kValid), "w.yaml"); });
  EXPECT_TRUE(Contains(short_error, "w.yaml: landmarks[0].text: '214'")) << short_error;
}

TEST(SaveTextMap, RefusesATextThatDoesNotFitTheRoomPattern) {
  test::TempDir dir;
  TextMap map;
  map.landmarks = {Plate("214", 0, 0, "w"), Plate("EXIT", 4, 0, "w")};
  const std::string error = ErrorOf<TextMapError>([&] { SaveTextMap(map, dir.Path("t.yaml")); });
  EXPECT_TRUE(Contains(error, dir.Path("t.yaml") + ": landmarks[1].text: 'EXIT'")) << error;
  EXPECT_TRUE(dir.List().empty());
}

TEST(ParseTextMap, EachBrokenFieldGivesAnErrorNamingTheFileAndField) {
  const std::string ok = kValid;
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string y = ok;
    y.replace(y.find(from), from.size(), to);
    return y;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {with("wall: north}", "wall: north, colour: red}"), "landmarks[0]: unknown field 'colour'"},
      {ok + "owner: me\n", "(top level): unknown field 'owner'"},
      {with("index: 1", "index: 0"), "landmarks[1].index: duplicate index 0 (also landmarks[0])"},
      {with("index: 1", "index: 2"), "landmarks[0].index: must be within 0..1"},
      {with("to: 1", "to: 5"), "adjacent[0].to: no landmark with index 5 (the map has 2)"},
      {with("from: 0", "from: -1"), "adjacent[0].from: no landmark with index -1"},
      {with("to: 1", "to: 0"), "adjacent[0].to: must differ from 'from'"},
      {with("x_m: 6.0", "x_m: .nan"), "landmarks[0].x_m: must be a finite number"},
      {with("text: \"214\"", "text: \"\""), "landmarks[0].text: must not be empty"},
      {with("y_m: 2.2, yaw_rad", "yaw_rad"), "landmarks[0].y_m: required field is missing"},
      {with("format_version: 1", "format_version: 2"), "format_version: unsupported version 2"},
      {with("source: odometry", "source: guess"), "adjacent[0].source: must be 'map' or 'odometry'"},
      {with("distance_m: 4.0", "distance_m: -1"), "adjacent[0].distance_m: must be >= 0"},
      {ok + "  - {from: 0, to: 1, distance_m: 4.5, source: odometry}\n", "adjacent[1]: duplicate entry for 0 -> 1"},
      {with("observations: 3", "observations: -3"), "landmarks[1].observations: must be >= 0"},
      {with("frame_id: map", "frame_id: \"\""), "frame_id: must not be empty"},
      {with("frame_id: map", "frame_id: map\nroom_pattern: \"[0-9\""), "room_pattern: room pattern \"[0-9\" is not a valid"},
      {with("frame_id: map", "frame_id: map\nroom_pattern: \"\""), "room_pattern: room pattern must not be empty"},
      {with("text: \"214\"", "text: \"EXIT\""), "landmarks[0].text: 'EXIT' (canonical 'EXIT') does not fit room_pattern"},
  };
  for (const auto& [yaml, expected] : cases) {
    const std::string error = ErrorOf<TextMapError>([&] { ParseTextMap(yaml, "maps/w.text_map.yaml"); });
    EXPECT_TRUE(Contains(error, "maps/w.text_map.yaml: " + expected)) << error;
  }
}

TEST(LoadTextMap, AMissingFileIsNamed) {
  const std::string error = ErrorOf<TextMapError>([] { LoadTextMap("/nonexistent/t.yaml"); });
  EXPECT_TRUE(Contains(error, "/nonexistent/t.yaml: cannot open")) << error;
}

TEST(ComputeAdjacentDistances, SortsEachWallsPlatesAlongItsDirection) {
  TextMap map;
  const double c = std::cos(0.5), s = std::sin(0.5);  // a wall at 0.5 rad, plates listed out of order
  map.landmarks = {Plate("3", 7 * c, 7 * s, "diag"), Plate("1", 1 * c, 1 * s, "diag"),
                   Plate("2", 4 * c, 4 * s, "diag")};
  ComputeAdjacentDistances(&map);
  ASSERT_EQ(map.adjacent.size(), 2u);
  EXPECT_EQ(map.adjacent[0].from, 1);
  EXPECT_EQ(map.adjacent[0].to, 2);
  EXPECT_NEAR(map.adjacent[0].distance_m, 3.0, 1e-9);
  EXPECT_EQ(map.adjacent[1].from, 2);
  EXPECT_EQ(map.adjacent[1].to, 0);
  EXPECT_NEAR(map.adjacent[1].distance_m, 3.0, 1e-9);
  EXPECT_EQ(map.adjacent[1].source, "map");
}

TEST(ComputeAdjacentDistances, ProjectsOntoTheWallAndRunsUpAVerticalWall) {
  TextMap map;
  map.landmarks = {Plate("b", 0.02, 5.0, "west"), Plate("a", -0.02, 1.0, "west")};
  ComputeAdjacentDistances(&map);
  ASSERT_EQ(map.adjacent.size(), 1u);
  EXPECT_EQ(map.adjacent[0].from, 1);  // increasing y
  EXPECT_NEAR(map.adjacent[0].distance_m, 4.0, 1e-3);
}

TEST(ComputeAdjacentDistances, NeverLinksDifferentOrUnlabelledWallsAndKeepsOdometryEntries) {
  TextMap map;
  map.landmarks = {Plate("1", 0, 0, "south"), Plate("2", 4, 2.2, "north"), Plate("3", 8, 0, "south"),
                   Plate("4", 9, 0, "")};
  map.adjacent = {{0, 1, 4.1, "odometry"}, {1, 3, 1.0, "map"}};
  ComputeAdjacentDistances(&map);
  ASSERT_EQ(map.adjacent.size(), 2u);
  EXPECT_EQ(map.adjacent[0].source, "odometry");
  EXPECT_EQ(map.adjacent[1].from, 0);
  EXPECT_EQ(map.adjacent[1].to, 2);
  EXPECT_NEAR(map.adjacent[1].distance_m, 8.0, 1e-12);
}

}  // namespace
}  // namespace doorplate_localization
