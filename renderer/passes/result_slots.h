#pragma once
// A frame's results by type (Filament's Blackboard, typed): each pass puts its own result
// type after the fence (FramePass::collect) and readers ask for it by type,
// frame.find<HizResult>(). A slot may carry the function that writes the pass's report.json
// section, so the report iterates what the passes put, in pass order, and names no pass.
#include <functional>
#include <memory>
#include <typeindex>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace ds {

struct FrameResult;

// Writes one pass's section(s) into report.json's object; `frame` for joins with frame facts.
template <typename T>
using ReportWriter = void (*)(const T& result, const FrameResult& frame, nlohmann::json& report);

class ResultSlots {
  public:
    // Stores `value` (replacing one of the same type) with its report writer (none: not in the
    // report).
    template <typename T>
    T& put(T value, ReportWriter<T> writer = nullptr) {
        auto stored = std::make_shared<T>(std::move(value));
        Slot slot{std::type_index(typeid(T)), stored, {}};
        if (writer)
            slot.write = [writer](const void* v, const FrameResult& f, nlohmann::json& r) {
                writer(*static_cast<const T*>(v), f, r);
            };
        for (Slot& s : slots_)
            if (s.type == slot.type) return s = std::move(slot), *stored;
        slots_.push_back(std::move(slot));
        return *stored;
    }
    template <typename T>
    const T* find() const {
        for (const Slot& s : slots_)
            if (s.type == std::type_index(typeid(T))) return static_cast<const T*>(s.value.get());
        return nullptr;
    }
    template <typename T>
    T* find() {
        return const_cast<T*>(std::as_const(*this).find<T>());
    }
    // Every slot's report section, in the order they were put.
    void write_report(const FrameResult& frame, nlohmann::json& report) const {
        for (const Slot& s : slots_)
            if (s.write) s.write(s.value.get(), frame, report);
    }

  private:
    struct Slot {
        std::type_index type;
        std::shared_ptr<void> value;
        std::function<void(const void*, const FrameResult&, nlohmann::json&)> write;
    };
    std::vector<Slot> slots_;
};

}  // namespace ds
