#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/settings/knob.h"
#include "renderer/settings/settings.h"

using ds::Settings;
using ds::SettingsRegistry;
using ds::UsageError;

namespace {

// This binary links the settings layer alone: the frame-wide knobs, and these two declared the
// way a pass or a scene declares its own.
constexpr ds::Knob<int> kTestLayers{"test_layers"};
constexpr ds::Knob<int> kTestPairs{"test_pairs"};
std::vector<ds::SettingDef> test_knobs() {
    return {
        ds::int_knob(kTestLayers, "scene", 8, 1, 64, "test: an int knob", ds::Invalidates::Scene),
        ds::int_knob(kTestPairs, "scene", 6, 1, 16, "test: another", ds::Invalidates::Scene),
        ds::int_knob(ds::Knob<int>{"test_steps"}, "diagnostics", 4, 0, 1024, "test: 0..1024",
                     ds::Invalidates::Nothing)};
}
const ds::KnobSource kTestKnobs(ds::KnobOwner::Scenes, &test_knobs);

// Runs `fn`, expects a UsageError and returns its message.
template <typename Fn>
std::string usage_error_of(Fn&& fn) {
    try {
        fn();
    } catch (const UsageError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no UsageError thrown";
    return {};
}

}  // namespace

TEST(Settings, DefaultsComeFromTheRegistry) {
    Settings s;
    for (const auto& def : SettingsRegistry::instance().all()) {
        EXPECT_EQ(s.get(def.name), def.default_value) << def.name;
        EXPECT_FALSE(def.help.empty()) << def.name;
    }
    EXPECT_EQ(s.get_int("test_layers"), 8);
}

// Frame-wide knobs come first, then the declared ones; a typed handle reads its knob.
TEST(Settings, DeclaredKnobsFollowTheFrameWideOnes) {
    const auto& all = SettingsRegistry::instance().all();
    ASSERT_GE(all.size(), 3u);
    EXPECT_EQ(all.front().name, "prepass");
    EXPECT_EQ(all[all.size() - 3].name, "test_layers");
    EXPECT_EQ(all[all.size() - 2].name, "test_pairs");
    Settings s;
    s.set("test_pairs", "3");
    EXPECT_EQ(ds::knob_value(s, kTestPairs), 3);
    EXPECT_EQ(ds::knob_value(s, kTestLayers), 8);
}

TEST(Settings, UnknownNameListsValidNames) {
    Settings s;
    const std::string msg = usage_error_of([&] { s.set("test_layer", "3"); });
    EXPECT_NE(msg.find("unknown setting 'test_layer'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("test_layers"), std::string::npos) << msg;
    EXPECT_NE(msg.find("exposure"), std::string::npos) << msg;
}

TEST(Settings, IntRangeAndTypeAreChecked) {
    Settings s;
    s.set("test_layers", "12");
    EXPECT_EQ(s.get_int("test_layers"), 12);
    EXPECT_NE(usage_error_of([&] { s.set("test_layers", "0"); }).find("out of range 1..64"),
              std::string::npos);
    EXPECT_NE(usage_error_of([&] { s.set("test_layers", "2.5"); }).find("not an integer"),
              std::string::npos);
    EXPECT_NE(usage_error_of([&] { s.set("test_layers", "many"); }).find("not a number"),
              std::string::npos);
    EXPECT_EQ(s.get_int("test_layers"), 12);  // a rejected value leaves the old one
}

TEST(Settings, FloatsAreCanonicalised) {
    Settings s;
    s.set("exposure", "2.50");
    EXPECT_EQ(s.get("exposure"), "2.5");
    EXPECT_FLOAT_EQ(s.get_float("exposure"), 2.5f);
    EXPECT_NE(usage_error_of([&] { s.set("exposure", "nan"); }).find("not a number"),
              std::string::npos);
    EXPECT_NE(usage_error_of([&] { s.set("exposure", "1e9"); }).find("out of range"),
              std::string::npos);
}

TEST(Settings, ApplyParsesAssignments) {
    Settings s;
    s.apply("test_pairs=3");
    EXPECT_EQ(s.get_int("test_pairs"), 3);
    EXPECT_NE(usage_error_of([&] { s.apply("test_pairs"); }).find("name=value"), std::string::npos);
    EXPECT_NE(usage_error_of([&] { s.apply("=3"); }).find("name=value"), std::string::npos);
}

TEST(Settings, DiffNamesChangedKnobs) {
    Settings a, b;
    EXPECT_TRUE(a.diff(b).empty());
    b.set("exposure", "2");
    ASSERT_EQ(a.diff(b).size(), 1u);
    EXPECT_EQ(a.diff(b)[0], "exposure");
}

TEST(Settings, RangeTextDescribesEachType) {
    const auto& reg = SettingsRegistry::instance();
    EXPECT_EQ(reg.at("test_layers").range_text(), "1..64");
    EXPECT_EQ(reg.at("test_layers").type_name(), "int");
    EXPECT_THROW(reg.at("nope"), UsageError);
}

TEST(Settings, FloatWithKeyword) {
    Settings s;
    EXPECT_EQ(s.get("alpha_cutoff"), "material");
    EXPECT_THROW(s.get_float("alpha_cutoff"), UsageError);
    s.set("alpha_cutoff", "0.25");
    EXPECT_FLOAT_EQ(s.get_float("alpha_cutoff"), 0.25f);
    s.set("alpha_cutoff", "material");
    EXPECT_EQ(s.get("alpha_cutoff"), "material");
    EXPECT_NE(usage_error_of([&] { s.set("alpha_cutoff", "1.5"); }).find("material|0..1"),
              std::string::npos);
    EXPECT_EQ(SettingsRegistry::instance().at("alpha_cutoff").range_text(), "material|0..1");
}

TEST(Settings, EnumsAndBools) {
    Settings s;
    EXPECT_TRUE(s.get_bool("prepass"));
    s.set("prepass", "false");
    EXPECT_EQ(s.get("prepass"), "off");
    EXPECT_EQ(s.get("depth_compare"), "equal");
    s.set("depth_compare", "greater_or_equal");
    EXPECT_NE(usage_error_of([&] {
                  s.set("depth_compare", "less");
              }).find("not one of equal|greater_or_equal"),
              std::string::npos);
    EXPECT_NE(usage_error_of([&] { s.set("reverse_z", "maybe"); }).find("on|off"),
              std::string::npos);
}

// material_alpha_cutoff: a Map (NAME=V pairs); the names are checked by the renderer against
// the scene, the syntax and values here.
TEST(Settings, MapIsCanonicalised) {
    Settings s;
    const auto& def = SettingsRegistry::instance().at("material_alpha_cutoff");
    EXPECT_EQ(def.type_name(), "map");
    EXPECT_EQ(def.range_text(), "NAME=0..1,...");
    EXPECT_EQ(s.get("material_alpha_cutoff"), "");
    EXPECT_TRUE(s.get_map("material_alpha_cutoff").empty());
    // Trimmed, sorted by name, numbers as floats are written; a name may hold spaces and '='.
    s.set("material_alpha_cutoff", " leaves = 0.30 , bark=1,material 3=.5e0 , a=b=0 ");
    EXPECT_EQ(s.get("material_alpha_cutoff"), "a=b=0,bark=1,leaves=0.3,material 3=0.5");
    const auto map = s.get_map("material_alpha_cutoff");
    ASSERT_EQ(map.size(), 4u);
    EXPECT_FLOAT_EQ(map.at("leaves"), 0.3f);
    EXPECT_FLOAT_EQ(map.at("material 3"), 0.5f);
    EXPECT_FLOAT_EQ(map.at("a=b"), 0.0f);
    // The canonical text reads back to itself (report.json -> --set reproduces a capture).
    Settings again;
    again.set("material_alpha_cutoff", s.get("material_alpha_cutoff"));
    EXPECT_TRUE(again.diff(s).empty());
    s.set("material_alpha_cutoff", "  ");
    EXPECT_EQ(s.get("material_alpha_cutoff"), "");
    // Through apply, as `--set material_alpha_cutoff=leaves=0.3` gives it: split at the first
    // '=' only.
    s.apply("material_alpha_cutoff=leaves=0.3");
    EXPECT_EQ(s.get("material_alpha_cutoff"), "leaves=0.3");
    EXPECT_THROW(s.get_map("alpha_cutoff"), UsageError);
}

TEST(Settings, MapRejectsBadEntriesInOneLine) {
    Settings s;
    s.set("material_alpha_cutoff", "leaves=0.25");
    const struct {
        const char* value;
        const char* mention;
    } cases[] = {
        {"leaves", "'leaves' is not NAME=V (expected NAME=V[,NAME=V...] with V in 0..1)"},
        {"leaves=0.3,", "empty entry in 'leaves=0.3,'"},
        {",leaves=0.3", "empty entry"},
        {"=0.3", "'=0.3' has no name"},
        {" =0.3", "has no name"},
        {"leaves=", "leaves: '' is not a number (map in 0..1)"},
        {"leaves=half", "leaves: 'half' is not a number (map in 0..1)"},
        {"leaves=nan", "not a number"},
        {"leaves=1.5", "leaves: 1.5 is out of range 0..1"},
        {"leaves=-0.1", "out of range 0..1"},
        {"leaves=0.3, leaves =0.4", "leaves is given twice"},
    };
    for (const auto& c : cases) {
        const std::string msg = usage_error_of([&] { s.set("material_alpha_cutoff", c.value); });
        EXPECT_EQ(msg.rfind("setting material_alpha_cutoff: ", 0), 0u) << c.value << ": " << msg;
        EXPECT_NE(msg.find(c.mention), std::string::npos) << c.value << ": " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
    EXPECT_EQ(s.get("material_alpha_cutoff"), "leaves=0.25");  // a rejected value leaves the old
}

TEST(Settings, FormatMapWritesWhatGetMapRead) {
    Settings s;
    s.set("material_alpha_cutoff", "b=0.70, a=0.3");
    const auto pairs = s.get_map("material_alpha_cutoff");
    EXPECT_EQ(ds::format_map(pairs), "a=0.3,b=0.7");
    EXPECT_EQ(ds::format_map(pairs), s.get("material_alpha_cutoff"));
    EXPECT_EQ(ds::format_map({}), "");
}
