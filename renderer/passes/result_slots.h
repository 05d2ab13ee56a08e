#pragma once
// A frame's results by type (Filament's Blackboard, typed): each pass puts its own result
// type after the fence (FramePass::collect) and readers ask for it by type,
// frame.find<HizResult>(). A slot may carry the function that writes the pass's report.json
// section, so the report iterates what the passes put, in pass order, and names no pass.
// Slots hold values (std::any): a copied FrameResult owns copies of its results.
#include <any>
#include <functional>
#include <typeinfo>
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
    // report); returns the stored value.
    template <typename T>
    T& put(T value, ReportWriter<T> writer = nullptr) {
        Slot slot{std::move(value), {}};
        if (writer)
            slot.write = [writer](const std::any& v, const FrameResult& f, nlohmann::json& r) {
                writer(*std::any_cast<T>(&v), f, r);
            };
        Slot* s = find_slot(typeid(T));
        if (s)
            *s = std::move(slot);
        else
            s = &slots_.emplace_back(std::move(slot));
        return *std::any_cast<T>(&s->value);
    }
    template <typename T>
    const T* find() const {
        const Slot* s = find_slot(typeid(T));
        return s ? std::any_cast<T>(&s->value) : nullptr;
    }
    template <typename T>
    T* find() {
        Slot* s = find_slot(typeid(T));
        return s ? std::any_cast<T>(&s->value) : nullptr;
    }
    // Every slot's report section, in the order they were put.
    void write_report(const FrameResult& frame, nlohmann::json& report) const {
        for (const Slot& s : slots_)
            if (s.write) s.write(s.value, frame, report);
    }

  private:
    struct Slot {
        std::any value;
        std::function<void(const std::any&, const FrameResult&, nlohmann::json&)> write;
    };
    const Slot* find_slot(const std::type_info& type) const {
        for (const Slot& s : slots_)
            if (s.value.type() == type) return &s;
        return nullptr;
    }
    Slot* find_slot(const std::type_info& type) {
        return const_cast<Slot*>(std::as_const(*this).find_slot(type));
    }
    std::vector<Slot> slots_;
};

}  // namespace ds
