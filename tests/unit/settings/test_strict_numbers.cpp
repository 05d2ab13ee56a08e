// Strict numbers (issue 12): a value is refused when parsing it, never later by a conversion
// (a denormal used to pass the registry and fail the frame in stof); a user's text in an error
// message has its control characters escaped, so the message stays one line.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/settings/settings.h"

using ds::Settings;
using ds::SettingsRegistry;
using ds::SettingType;
using ds::UsageError;

namespace {

std::string strict_usage_error(Settings& s, const std::string& name, const std::string& value) {
    try {
        s.set(name, value);
    } catch (const UsageError& e) {
        return e.what();
    }
    ADD_FAILURE() << name << "=" << value << ": no UsageError";
    return {};
}

}  // namespace

TEST(StrictNumbers, DenormalsAndValuesBelowTheSmallestNormalFloatAreRefused) {
    Settings s;
    // 1.17549436e-38 lies just above FLT_MIN, but its stored text (7 digits, 1.175494e-38) does
    // not: the check is on what get_float() will read.
    for (const char* v :
         {"1e-320", "4.9e-324", "1e-40", "1e-38", "1.1754942e-38", "1.17549436e-38"}) {
        const std::string msg = strict_usage_error(s, "sun_intensity", v);
        EXPECT_NE(msg.find("too small for a float"), std::string::npos) << v << ": " << msg;
    }
    // Below double's range altogether: not a number at all (from_chars reports the range).
    EXPECT_FALSE(strict_usage_error(s, "sun_intensity", "1e-400").empty());
    EXPECT_EQ(s.get("sun_intensity"), "3");  // every refusal left the default
    // The smallest normal float and just above it read back as themselves, normal.
    for (const char* v : {"1.2e-38", "1.175495e-38", "0.0001"}) {
        s.set("sun_intensity", v);
        const float f = s.get_float("sun_intensity");
        EXPECT_TRUE(std::isnormal(f)) << v << " -> " << s.get("sun_intensity");
    }
    // The same rule for a Map's numbers.
    const std::string msg = strict_usage_error(s, "material_alpha_cutoff", "a=1e-320");
    EXPECT_NE(msg.find("too small for a float"), std::string::npos) << msg;
}

TEST(StrictNumbers, ZeroAndNegativeZeroAreZero) {
    Settings s;
    s.set("sun_intensity", "-0");
    EXPECT_EQ(s.get("sun_intensity"), "0");
    s.set("sun_intensity", "0.0");
    EXPECT_EQ(s.get_float("sun_intensity"), 0.0f);
}

TEST(StrictNumbers, OnlyWholePlainNumbersAreNumbers) {
    Settings s;
    for (const char* v :
         {"", " 2", "2 ", "+2", "0x2", "2,5", "inf", "-inf", "nan", "1e999", "2f", "\n2", "２"}) {
        const std::string msg = strict_usage_error(s, "exposure", v);
        EXPECT_NE(msg.find("not a number"), std::string::npos) << "'" << v << "': " << msg;
    }
    EXPECT_EQ(s.get("exposure"), "1");
}

TEST(StrictNumbers, IntKnobsStayInsideTheirRangeAndInt) {
    Settings s;
    for (const char* v :
         {"2147483648", "-2147483649", "4294967297", "1e10", "99999999999999999999"})
        EXPECT_NE(strict_usage_error(s, "test_layers", v).find("out of range 1..64"),
                  std::string::npos)
            << v;
    EXPECT_NE(strict_usage_error(s, "test_steps", "1e-320").find("not an integer"),
              std::string::npos);
    s.set("test_steps", "1e3");  // an exponent that makes a whole number is that number
    EXPECT_EQ(s.get("test_steps"), "1000");
    EXPECT_EQ(s.get_int("test_steps"), 1000);
}

TEST(StrictNumbers, MsaaTakesOnlyVulkanSampleCounts) {
    Settings s;
    for (const char* v : {"3", "5", "6", "7"}) {
        const std::string msg = strict_usage_error(s, "msaa", v);
        EXPECT_NE(msg.find("setting msaa: " + std::string(v) + " is not one of 1|2|4|8"),
                  std::string::npos)
            << msg;
    }
    EXPECT_NE(strict_usage_error(s, "msaa", "16").find("out of range"), std::string::npos);
    for (const char* v : {"1", "2", "4", "8", "4.0"}) {
        s.set("msaa", v);
        EXPECT_EQ(s.get_int("msaa"), std::stoi(v));
    }
    EXPECT_EQ(SettingsRegistry::instance().at("msaa").range_text(), "1|2|4|8");
}

// get_int / get_float read text that set() made canonical: every knob's default and a value
// at each end of its range read back without a std exception.
TEST(StrictNumbers, EveryNumericKnobReadsBackAtItsBounds) {
    for (const auto& def : SettingsRegistry::instance().all()) {
        if (def.type != SettingType::Int && def.type != SettingType::Float) continue;
        Settings s;
        for (const double bound : {def.min, def.max}) {
            if (def.type == SettingType::Int && !def.choices.empty()) continue;  // msaa above
            char text[64];
            std::snprintf(text, sizeof text, "%.17g", bound);
            s.set(def.name, text);
            if (def.type == SettingType::Int) {
                EXPECT_EQ(s.get_int(def.name), int(bound)) << def.name;
            } else {
                EXPECT_NEAR(s.get_float(def.name), bound, std::fabs(bound) * 1e-6) << def.name;
            }
        }
    }
}

TEST(Quoted, ControlCharactersAreEscapedAndTheRestKept) {
    EXPECT_EQ(ds::quote("on\noff"), "'on\\noff'");
    EXPECT_EQ(ds::escaped("a\tb\rc"), "a\\tb\\rc");
    EXPECT_EQ(ds::escaped(std::string("x\0y", 3)), "x\\x00y");
    EXPECT_EQ(ds::escaped("\x1b[31m\x7f"), "\\x1b[31m\\x7f");
    EXPECT_EQ(ds::escaped("C:\\path é"), "C:\\path é");  // backslashes and UTF-8 stay
    const std::string once = ds::escaped("a\nb\x01");
    EXPECT_EQ(ds::escaped(once), once);  // escaping twice changes nothing
}

TEST(Quoted, EverySettingsErrorThatEchoesAValueStaysOneLine) {
    Settings s;
    const struct {
        const char* name;
        const char* value;
    } cases[] = {{"prepass", "on\noff"},
                 {"depth_compare", "equal\n"},
                 {"exposure", "1\n2"},
                 {"test_layers", "1\r"},
                 {"material_alpha_cutoff", "a\nb"},
                 {"material_alpha_cutoff", "\x01=0.5,\x01=0.5"},
                 {"material_alpha_cutoff", "=\n0.5"}};
    for (const auto& c : cases) {
        const std::string msg = strict_usage_error(s, c.name, c.value);
        EXPECT_EQ(msg.find_first_of("\n\r\x01"), std::string::npos) << c.name << ": " << msg;
    }
    try {
        s.apply("no\nsuch=1");
        ADD_FAILURE() << "no error";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown setting 'no\\nsuch'"), std::string::npos)
            << e.what();
    }
}
