// PassBuilder (setup: declarations) and PassContext (record: resolved handles).
#include <algorithm>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/graph/graph.h"
#include "renderer/graph/names.h"

namespace ds::graph {
namespace {

bool uses_shader_stage(Access access) {
    return access == Access::Sampled || access == Access::StorageRead ||
           access == Access::StorageWrite || access == Access::StorageReadWrite ||
           access == Access::UniformRead;
}

bool is_depth_kind(Access access) {
    return access == Access::DepthAttachment || access == Access::DepthReadOnly;
}

bool is_attachment_kind(Access access) {
    return access == Access::ColorAttachment || is_depth_kind(access) ||
           access == Access::ResolveDst || access == Access::InputAttachment;
}

[[noreturn]] void throw_attachment_kind(const RenderGraph& graph, uint32_t pass, ImageHandle image,
                                        Access access) {
    const auto& resources = graph.resources();
    const std::string name =
        image.index < resources.size() ? resources[image.index].name : std::string("?");
    throw Error("render graph: pass '" + graph.passes()[pass].name + "', '" + name +
                "': " + access_name(access) +
                " is an attachment: declare it with color(), depth(), resolve() or input()");
}

}  // namespace

ImageHandle PassBuilder::create_image(const std::string& name, const ImageDesc& desc) {
    if (desc.format == VK_FORMAT_UNDEFINED)
        throw Error("render graph: image '" + name + "' has no format");
    if (desc.mip_levels == 0 || (desc.samples != VK_SAMPLE_COUNT_1_BIT && desc.mip_levels != 1))
        throw Error("render graph: image '" + name + "': multisampled images have one mip level");
    ResourceInfo info;
    info.name = name;
    info.image = desc;
    info.extent = desc.size.resolve(graph_.output_);
    return {graph_.add_resource(std::move(info))};
}

HistoryImage PassBuilder::create_history(const std::string& name, const ImageDesc& desc) {
    const ImageHandle previous = create_image(name + ".previous", desc);
    const ImageHandle current = create_image(name + ".current", desc);
    for (auto [handle, role] :
         {std::pair{previous, HistoryRole::Previous}, std::pair{current, HistoryRole::Current}}) {
        graph_.resources_[handle.index].lifetime = Lifetime::History;
        graph_.resources_[handle.index].history = role;
    }
    graph_.histories_.push_back({name, previous.index, current.index, nullptr});
    return {previous, current};
}

BufferHandle PassBuilder::create_buffer(const std::string& name, const BufferDesc& desc) {
    if (desc.size == 0) throw Error("render graph: buffer '" + name + "' is empty");
    ResourceInfo info;
    info.name = name;
    info.is_image = false;
    info.size = desc.size;
    info.memory = desc.memory;
    return {graph_.add_resource(std::move(info))};
}

void PassBuilder::declare(uint32_t resource, bool image, Access access, Shader shader, bool write) {
    PassInfo& pass = graph_.passes_[pass_];
    const ResourceInfo& r = graph_.resource(resource, image, write ? "write()" : "read()");
    const std::string where = "render graph: pass '" + pass.name + "', '" + r.name + "': ";
    if (is_write(access) != write)
        throw Error(where + access_name(access) + " is " + (write ? "not a write" : "a write") +
                    ": declare it with " + (write ? "read()" : "write()"));
    if (image ? is_buffer_only(access) : is_image_only(access))
        throw Error(where + access_name(access) + " does not apply to " +
                    (image ? "an image" : "a buffer"));
    if (image && access != Access::ResolveDst && is_depth_kind(access) != r.depth() &&
        (is_depth_kind(access) || access == Access::ColorAttachment))
        throw Error(where + access_name(access) + " does not fit format " +
                    format::name(r.image.format));
    const bool attachment = access == Access::ColorAttachment || is_depth_kind(access) ||
                            access == Access::ResolveDst || access == Access::InputAttachment;
    if (pass.kind != PassKind::Graphics && attachment)
        throw Error(where + "a " + pass_kind_name(pass.kind) + " pass has no attachments");
    if (pass.kind == PassKind::Transfer && uses_shader_stage(access))
        throw Error(where + "a transfer pass runs no shader (" + access_name(access) + ")");
    if (uses_shader_stage(access) && shader == Shader::Default)
        shader = pass.kind == PassKind::Compute ? Shader::Compute : Shader::Fragment;
    pass.accesses.push_back({resource, access, shader});
}

ImageHandle PassBuilder::read(ImageHandle image, Access access, Shader shader) {
    if (is_attachment_kind(access)) throw_attachment_kind(graph_, pass_, image, access);
    declare(image.index, true, access, shader, false);
    return image;
}

ImageHandle PassBuilder::write(ImageHandle image, Access access, Shader shader) {
    if (is_attachment_kind(access)) throw_attachment_kind(graph_, pass_, image, access);
    declare(image.index, true, access, shader, true);
    return image;
}

BufferHandle PassBuilder::read(BufferHandle buffer, Access access, Shader shader) {
    declare(buffer.index, false, access, shader, false);
    return buffer;
}

BufferHandle PassBuilder::write(BufferHandle buffer, Access access, Shader shader) {
    declare(buffer.index, false, access, shader, true);
    return buffer;
}

PassInfo& PassBuilder::attaching(const char* what) {
    PassInfo& pass = graph_.passes_[pass_];
    if (pass.kind != PassKind::Graphics)
        throw Error("render graph: pass '" + pass.name + "': " + what + ": a " +
                    pass_kind_name(pass.kind) + " pass renders nothing");
    return pass;
}

ImageHandle PassBuilder::color(ImageHandle image, const ColorUse& use) {
    declare(image.index, true, Access::ColorAttachment, Shader::Default, true);
    AttachmentDecl d{
        .kind = AttachmentDecl::Kind::Color, .resource = image.index, .load = use.load};
    d.clear.color = use.clear;
    attaching("color()").attachments.push_back(d);
    return image;
}

void PassBuilder::unused_color(VkFormat format) {
    attaching("unused_color()")
        .attachments.push_back({.kind = AttachmentDecl::Kind::UnusedColor, .format = format});
}

ImageHandle PassBuilder::depth(ImageHandle image, const DepthUse& use) {
    declare(image.index, true, use.read_only ? Access::DepthReadOnly : Access::DepthAttachment,
            Shader::Default, !use.read_only);
    AttachmentDecl d{.kind = AttachmentDecl::Kind::Depth,
                     .resource = image.index,
                     .load = use.load,
                     .read_only = use.read_only};
    d.clear.depthStencil = {use.clear, 0};
    PassInfo& pass = attaching("depth()");
    for (const AttachmentDecl& x : pass.attachments)
        if (x.kind == AttachmentDecl::Kind::Depth)
            throw Error("render graph: pass '" + pass.name +
                        "' declares a second depth attachment");
    pass.attachments.push_back(d);
    return image;
}

ImageHandle PassBuilder::resolve(ImageHandle from, ImageHandle into, VkResolveModeFlagBits mode) {
    declare(into.index, true, Access::ResolveDst, Shader::Default, true);
    attaching("resolve()")
        .attachments.push_back({.kind = AttachmentDecl::Kind::Resolve,
                                .resource = into.index,
                                .resolves = from.index,
                                .mode = mode});
    return into;
}

ImageHandle PassBuilder::input(ImageHandle image) {
    declare(image.index, true, Access::InputAttachment, Shader::Default, false);
    attaching("input()").attachments.push_back(
        {.kind = AttachmentDecl::Kind::Input, .resource = image.index});
    return image;
}

void PassBuilder::render_area(VkExtent2D extent) {
    attaching("render_area()").render_area = extent;
}

void PassBuilder::render_pass() {
    attaching("render_pass()").render_pass = true;
}

void PassBuilder::outside_rendering(std::function<void(VkCommandBuffer)> record) {
    graph_.prologues_[pass_].push_back(std::move(record));
}

VkExtent2D PassBuilder::output_extent() const {
    return graph_.output_;
}

VkExtent2D PassBuilder::extent(ImageHandle image) const {
    return graph_.resource(image.index, true, "extent()").extent;
}

const std::string& PassContext::pass_name() const {
    return graph_.passes_[pass_].name;
}

const PassUse& PassContext::use(uint32_t resource) const {
    const auto& uses = graph_.plan_.passes[pass_].uses;
    auto it = std::find_if(uses.begin(), uses.end(),
                           [&](const PassUse& u) { return u.resource == resource; });
    if (it == uses.end())
        throw Error("render graph: pass '" + pass_name() + "' did not declare '" +
                    graph_.resources_[resource].name + "'");
    return *it;
}

VkImage PassContext::image(ImageHandle h) const {
    graph_.resource(h.index, true, "image()");
    use(h.index);
    return graph_.bindings_[h.index].image;
}

VkImageView PassContext::view(ImageHandle h) const {
    graph_.resource(h.index, true, "view()");
    use(h.index);
    return graph_.bindings_[h.index].view;
}

VkImageLayout PassContext::layout(ImageHandle h) const {
    graph_.resource(h.index, true, "layout()");
    return use(h.index).use.layout;
}

VkBuffer PassContext::buffer(BufferHandle h) const {
    graph_.resource(h.index, false, "buffer()");
    use(h.index);
    return graph_.bindings_[h.index].buffer;
}

VkExtent2D PassContext::extent(ImageHandle h) const {
    return graph_.resource(h.index, true, "extent()").extent;
}

VkFormat PassContext::format(ImageHandle h) const {
    return graph_.resource(h.index, true, "format()").image.format;
}

VkDeviceSize PassContext::size(BufferHandle h) const {
    return graph_.resource(h.index, false, "size()").size;
}

void PassContext::dependency(ImageHandle h, Access before, Access after) const {
    const ResourceInfo& r = graph_.resource(h.index, true, "dependency()");
    const PassInfo& pass = graph_.passes_[pass_];
    auto declared = [&](Access a) {
        return std::any_of(pass.accesses.begin(), pass.accesses.end(), [&](const AccessInfo& i) {
            return i.resource == h.index && i.access == a;
        });
    };
    if (pass.renders())
        throw Error("render graph: pass '" + pass.name +
                    "' renders: a barrier inside its rendering would be a self-dependency");
    if (!declared(before) || !declared(after))
        throw Error("render graph: pass '" + pass.name + "', '" + r.name +
                    "': dependency() between accesses it did not declare");
    auto shader_of = [&](Access a) {
        for (const AccessInfo& i : pass.accesses)
            if (i.resource == h.index && i.access == a) return i.shader;
        return Shader::Default;
    };
    const Use src = describe(before, shader_of(before), r.depth());
    const Use dst = describe(after, shader_of(after), r.depth());
    const VkImageLayout layout = use(h.index).use.layout;
    const Barrier b{.resource = h.index,
                    .is_image = true,
                    .old_layout = layout,
                    .new_layout = layout,
                    .src_stages = src.stages,
                    .src_access = write_bits(src.access),
                    .dst_stages = dst.stages,
                    .dst_access = dst.access};
    graph_.record_barriers(cmd_, {&b, 1});
}

const RenderTarget& PassContext::target() const {
    return graph_.targets_[pass_];
}

bool PassContext::history_valid(const HistoryImage& history) const {
    return graph_.resource(history.previous.index, true, "history_valid()").history_valid;
}

}  // namespace ds::graph
