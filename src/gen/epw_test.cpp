// Tests for epw2wea's conversion: header fields and their quirks (state for an empty
// country, "-0" time zone, atoi for the file and atof for the console), mid-interval
// hours, %.0f rounding, CRLF files, and one test per kind of bad file.
#include "gen/epw.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace rp::gen {
namespace {

std::string header(const std::string& location, const std::string& periods) {
    return location +
           "\nDESIGN CONDITIONS,0\nTYPICAL/EXTREME PERIODS,0\nGROUND TEMPERATURES,0\n"
           "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0\nCOMMENTS 1,x\nCOMMENTS 2,y\n" +
           periods + "\n";
}

// A record with direct normal and diffuse horizontal radiation as given.
std::string record(const std::string& date, const std::string& dir, const std::string& dif) {
    return date + ",60,?9?9,2.0,-1.9,76,83500,0,0,280,0," + dir + "," + dif + ",0,0,0,999\n";
}

EpwConversion convert(const std::string& text) {
    std::istringstream in(text);
    return epwToWea(in, "t.epw");
}

std::string errorOf(const std::string& text) {
    try {
        convert(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

const std::string kPeriods = "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31";

TEST(Epw, Conversion) {
    EpwConversion c =
        convert(header("LOCATION,Golden,CO,USA,TMY3,724666,39.74,-105.18,-7.0,1829.0", kPeriods) +
                record("2004,2,29,1", "0", "0") + record("2004,2,29,12", "437.5", "2.5"));
    const std::string head =
        "place Golden_USA\nlatitude 39.74\nlongitude 105.18\ntime_zone 105\n"
        "site_elevation 1829.0\nweather_data_file_units 1\n";
    EXPECT_EQ(c.wea, head + "2 29 0.500 0 0\n2 29 11.500 438 2\n");
    EXPECT_EQ(c.console,
              "place Golden_USA\nlatitude 39.74\nlongitude 105.18\ntime_zone 105.00\n"
              "site_elevation 1829.0\nweather_data_file_units 1\n");
}

TEST(Epw, Quirks) {
    // Empty country: the state stays; time zone 5.5 is 82.50 on the console, -75 (atoi)
    // in the file; time zone 0 prints as "-0"; CRLF lines and blank lines pass.
    std::string text = header("LOCATION,Pune,MH,,ISHRAE,430630,18.53,73.85,5.5,559.0", kPeriods) +
                       record("2001,6,21,7", "10", "20");
    EpwConversion c = convert(text);
    EXPECT_NE(c.wea.find("place Pune_MH\n"), std::string::npos);
    EXPECT_NE(c.wea.find("longitude -73.85\ntime_zone -75\n"), std::string::npos);
    EXPECT_NE(c.console.find("time_zone -82.50\n"), std::string::npos);
    std::string crlf = header("LOCATION,L,,GBR,I,0,51.15,-0.18,0.0,62.0", kPeriods) + "\n" +
                       record("1999,6,21,8", "326", "76");
    for (size_t at = 0; (at = crlf.find('\n', at)) != std::string::npos; at += 2)
        crlf.replace(at, 1, "\r\n");
    EpwConversion z = convert(crlf);
    EXPECT_EQ(z.wea,
              "place L_GBR\nlatitude 51.15\nlongitude 0.18\ntime_zone -0\nsite_elevation 62.0\n"
              "weather_data_file_units 1\n6 21 7.500 326 76\n");
    // Records per hour other than 1 are taken as minutes: 4 -> hour - 4/120.
    EpwConversion q = convert(header("LOCATION,a,b,c,d,e,1,2,3,4", "DATA PERIODS,1,4,Data") +
                              record("2001,1,1,1", "0", "0"));
    EXPECT_NE(q.wea.find("1 1 0.967 0 0\n"), std::string::npos);
}

TEST(Epw, BadFiles) {
    EXPECT_EQ(errorOf("place X\nlatitude 1\n"),
              "t.epw:1: this does not seem to be an epw file (no LOCATION line)");
    EXPECT_EQ(errorOf("LOCATION,a,b,c\n"), "t.epw:1: LOCATION line has 4 fields, expected 10");
    EXPECT_EQ(errorOf("LOCATION,a,b,c,d,e,1,2,3,4\nDESIGN CONDITIONS,0\n"),
              "t.epw:2: the file ends inside the 8 header lines");
    EXPECT_EQ(errorOf(header("LOCATION,a,b,c,d,e,1,2,3,4", "COMMENTS 3,z")),
              "t.epw:8: expected 'DATA PERIODS,count,records per hour,...' as the 8th line");
    std::string good = header("LOCATION,a,b,c,d,e,1,2,3,4", kPeriods);
    EXPECT_EQ(errorOf(good + "2001,1,1,1,60,x,1,2\n"),
              "t.epw:9: record has 8 fields, expected at least 16");
    EXPECT_EQ(errorOf(good + record("2001,Jan,1,1", "0", "0")),
              "t.epw:9: expected year, month, day and hour as whole numbers");
    EXPECT_EQ(errorOf(good + record("2001,1,1,1", "0", "0") + record("2001,1,1,2", "", "0")),
              "t.epw:10: expected direct normal and diffuse horizontal radiation (fields 15, "
              "16) as numbers");
}

}  // namespace
}  // namespace rp::gen
