#include "renderer/graph/cache.h"

#include <algorithm>

namespace ds::graph {
namespace {

template <typename Entry, typename Key>
Entry* find_unused(std::vector<std::unique_ptr<Entry>>& entries, const Key& key) {
    for (auto& e : entries)
        if (!e->used && e->key == key) return e.get();
    return nullptr;
}

template <typename Entry>
void retire(std::vector<std::unique_ptr<Entry>>& entries, vk::DestroyList& retired) {
    for (auto& e : entries)
        if (!e->used) retired.defer(std::move(*e));
    std::erase_if(entries, [](const std::unique_ptr<Entry>& e) { return !e->used; });
}

}  // namespace

bool ImageKey::operator==(const ImageKey& o) const {
    return name == o.name && format == o.format && extent.width == o.extent.width &&
           extent.height == o.extent.height && samples == o.samples && mip_levels == o.mip_levels &&
           usage == o.usage;
}

void ResourceCache::begin_frame() {
    for (auto& e : images_) e->used = false;
    for (auto& e : buffers_) e->used = false;
    for (auto& e : histories_) e->used = false;
}

vk::Image ResourceCache::create_image(const ImageKey& key, const std::string& name) {
    ++images_created_;
    return vk::Image(context_, vk::ImageDesc{key.extent.width, key.extent.height, key.mip_levels,
                                             key.format, key.usage, key.samples, name.c_str()});
}

CachedImage& ResourceCache::image(const ImageKey& key) {
    CachedImage* entry = find_unused(images_, key);
    if (!entry) {
        auto created = std::make_unique<CachedImage>();
        created->key = key;
        created->image = create_image(key, key.name);
        entry = images_.emplace_back(std::move(created)).get();
    }
    entry->used = true;
    return *entry;
}

CachedBuffer& ResourceCache::buffer(const BufferKey& key) {
    CachedBuffer* entry = find_unused(buffers_, key);
    if (!entry) {
        auto created = std::make_unique<CachedBuffer>();
        created->key = key;
        created->buffer =
            vk::Buffer(context_, vk::BufferDesc{key.size, key.usage, key.memory, key.name.c_str()});
        ++buffers_created_;
        entry = buffers_.emplace_back(std::move(created)).get();
    }
    entry->used = true;
    return *entry;
}

HistoryPair& ResourceCache::history(const ImageKey& key) {
    HistoryPair* entry = find_unused(histories_, key);
    if (!entry) {
        auto created = std::make_unique<HistoryPair>();
        created->key = key;
        created->images[0] = create_image(key, key.name + " (history A)");
        created->images[1] = create_image(key, key.name + " (history B)");
        entry = histories_.emplace_back(std::move(created)).get();
    }
    entry->used = true;
    return *entry;
}

void ResourceCache::retire_unused(vk::DestroyList& retired) {
    retire(images_, retired);
    retire(buffers_, retired);
    retire(histories_, retired);
}

void ResourceCache::invalidate_history() {
    for (auto& e : histories_) e->valid = false;
}

}  // namespace ds::graph
