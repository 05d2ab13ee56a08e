#pragma once
// How code declares and reads a knob (DESIGN "How to add a knob"). A knob is declared once, by what
// owns it: the frame-wide ones in frame_knobs.cpp, a pass's in its own file (gathered from the pass
// list), a built-in scene's in its scene file, the inspector's in ui/. The declaring file defines a
// typed handle (Knob<bool> kHiz{"hiz"}) that every reader uses, so a knob's name is spelled in one
// file and its type is checked by the compiler.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "renderer/settings/settings.h"

namespace ds {

// A Float knob that also takes a keyword ("material", "scene"): none when it holds the keyword.
struct OptionalFloat {};
// A Map knob (NAME=V pairs).
struct KnobMap {};
// An Enum knob, read as its canonical text.
struct KnobEnum {};

template <typename T>
struct Knob {
    const char* name;
};

bool knob_value(const Settings& s, Knob<bool> k);
int knob_value(const Settings& s, Knob<int> k);
float knob_value(const Settings& s, Knob<float> k);
std::optional<float> knob_value(const Settings& s, Knob<OptionalFloat> k);
const std::string& knob_value(const Settings& s, Knob<KnobEnum> k);
std::map<std::string, float, std::less<>> knob_value(const Settings& s, Knob<KnobMap> k);

// Sets a knob from text, as Settings::set (throws UsageError for a bad value).
template <typename T>
void set_knob(Settings& s, Knob<T> k, std::string_view value) {
    s.set(k.name, value);
}

// Declarations (SettingDef builders): the handle names the knob.
SettingDef bool_knob(Knob<bool> k, std::string group, bool def, std::string help, Invalidates inv);
SettingDef enum_knob(Knob<KnobEnum> k, std::string group, std::vector<std::string> choices,
                     std::string help, Invalidates inv);
// `allowed`: when given, the only values within min..max that the knob takes.
SettingDef int_knob(Knob<int> k, std::string group, int def, int min, int max, std::string help,
                    Invalidates inv, std::vector<std::string> allowed = {});
SettingDef float_knob(Knob<float> k, std::string group, std::string def, double min, double max,
                      std::string help, Invalidates inv);
// A number or `keyword` (the default when `def` is the keyword).
SettingDef optional_float_knob(Knob<OptionalFloat> k, std::string group, std::string keyword,
                               std::string def, double min, double max, std::string help,
                               Invalidates inv);
SettingDef map_knob(Knob<KnobMap> k, std::string group, double min, double max, std::string help,
                    Invalidates inv);

// The knobs of a list whose entries have `knobs` (a function returning their declarations,
// or null): the pass list's, the scene list's.
template <typename Entries>
std::vector<SettingDef> gather_knobs(const Entries& entries) {
    std::vector<SettingDef> out;
    for (const auto& e : entries)
        if (e.knobs)
            for (SettingDef& def : e.knobs()) out.push_back(std::move(def));
    return out;
}

// Where knobs come from beyond the frame-wide ones, in the order `depthscope settings` lists
// them: the frame's passes, the built-in scenes, the inspector.
enum class KnobOwner { Passes = 1, Scenes = 2, Inspector = 3 };

// Registers a declaring function with the registry (a namespace-scope object of the declaring
// layer, so lower layers never name higher ones). A binary has the knobs of the code it links:
// the object must sit in a file that is linked whenever its knobs are read (the pass list, the
// scene list, the inspector). Registering after the registry was first used aborts.
class KnobSource {
  public:
    using Declare = std::vector<SettingDef> (*)();
    KnobSource(KnobOwner owner, Declare declare);
};

}  // namespace ds
