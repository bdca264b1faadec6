// Tests for the weather tape reader: header fields, free white space, records with their
// line numbers, and one test per kind of bad tape.
#include "gen/wea.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace rp::gen {
namespace {

WeaTape read(const std::string& text) {
    std::istringstream in(text);
    return readWea(in, "t.wea");
}

std::string errorOf(const std::string& text) {
    try {
        read(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

const std::string kHead =
    "place Mountain View/Moffet N_USA\nlatitude 37.42\nlongitude 122.05\ntime_zone 120\n"
    "site_elevation 12.0\nweather_data_file_units 1\n";

TEST(Wea, HeaderAndRecords) {
    WeaTape t = read(kHead + "3 21 5.500 0 0\n\n3 21 6.500 10 42\r\n");
    EXPECT_EQ(t.header.place, "Mountain View/Moffet N_USA");
    EXPECT_EQ(t.header.latitude, 37.42);
    EXPECT_EQ(t.header.longitude, 122.05);
    EXPECT_EQ(t.header.timeZone, 120);
    EXPECT_EQ(t.header.elevation, 12);
    EXPECT_EQ(t.header.units, WeaUnits::DirectNormalIrradiance);
    ASSERT_EQ(t.records.size(), 2u);
    EXPECT_EQ(t.records[1].month, 3);
    EXPECT_EQ(t.records[1].day, 21);
    EXPECT_EQ(t.records[1].hour, 6.5);
    EXPECT_EQ(t.records[1].direct, 10);
    EXPECT_EQ(t.records[1].diffuse, 42);
    EXPECT_EQ(t.records[1].line, 9);
}

TEST(Wea, WhiteSpaceIsFreeInTheHeader) {
    WeaTape t = read(
        "place  X\r\n  latitude\t-33.9 longitude -18.6\n\ntime_zone -30 site_elevation 5 "
        "weather_data_file_units 3\n");
    EXPECT_EQ(t.header.place, "X");
    EXPECT_EQ(t.header.latitude, -33.9);
    EXPECT_EQ(t.header.timeZone, -30);
    EXPECT_EQ(t.header.units, WeaUnits::DirectNormalIlluminance);
    EXPECT_TRUE(t.records.empty());
}

TEST(Wea, BadHeader) {
    EXPECT_EQ(errorOf("latitude 3\n"),
              "t.wea:1: weather tape format error in header: expected 'place name' on the "
              "first line");
    EXPECT_EQ(errorOf("place X\nlongitude 3\n"),
              "t.wea:2: weather tape format error in header: expected 'latitude <degrees "
              "north>'");
    EXPECT_NE(errorOf("place X\nlatitude north\n").find("t.wea:2: weather tape format error"),
              std::string::npos);
    std::string units4 = kHead.substr(0, kHead.size() - 2) + "4\n";
    EXPECT_EQ(errorOf(units4),
              "t.wea:6: weather tape format error in header: weather_data_file_units must be "
              "1, 2 or 3");
}

TEST(Wea, BadRecords) {
    EXPECT_EQ(errorOf(kHead + "3 21 5.5 0 0\n3 21 6.5 0\n"),
              "t.wea:8: expected 'month day hour direct diffuse', got 4 words");
    EXPECT_EQ(errorOf(kHead + "3 21 5.5 0 0 7\n"),
              "t.wea:7: expected 'month day hour direct diffuse', got 6 words");
    EXPECT_EQ(errorOf(kHead + "3 21 five 0 0\n"),
              "t.wea:7: expected 'month day hour direct diffuse' as numbers");
    EXPECT_EQ(errorOf(kHead + "3.5 21 5 0 0\n"),
              "t.wea:7: expected 'month day hour direct diffuse' as numbers");
    EXPECT_EQ(errorOf(kHead + "13 21 5 0 0\n"), "t.wea:7: bad month 13: expected 1..12");
    EXPECT_EQ(errorOf(kHead + "4 31 5 0 0\n"), "t.wea:7: bad day 31: month 4 has days 1..30");
}

}  // namespace
}  // namespace rp::gen
