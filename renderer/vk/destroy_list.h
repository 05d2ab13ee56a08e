#pragma once
// Per-frame deferred destruction (DESIGN decision 9): an object the GPU may still use is
// moved here and dies when this frame slot's fence has signalled, never earlier.
#include <memory>
#include <utility>
#include <vector>

namespace ds::vk {

class DestroyList {
  public:
    DestroyList() = default;
    DestroyList(DestroyList&&) = default;
    DestroyList& operator=(DestroyList&&) = default;
    ~DestroyList() { flush(); }

    // Takes ownership of any movable RAII object (Image, Buffer, Pipeline, ...).
    template <typename T>
    void defer(T&& object) {
        entries_.push_back(std::make_unique<Holder<std::decay_t<T>>>(std::forward<T>(object)));
    }
    // Destroys everything, newest first (the reverse of creation, as for scoped objects).
    void flush() {
        while (!entries_.empty()) entries_.pop_back();
    }
    size_t size() const { return entries_.size(); }

  private:
    struct Entry {
        virtual ~Entry() = default;
    };
    template <typename T>
    struct Holder : Entry {
        explicit Holder(T&& v) : value(std::move(v)) {}
        T value;
    };
    std::vector<std::unique_ptr<Entry>> entries_;
};

}  // namespace ds::vk
