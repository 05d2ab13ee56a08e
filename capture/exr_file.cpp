#include "capture/exr_file.h"

#include <exception>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>

#include "capture/file_output.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::capture {
namespace {

// What read_exr takes in at most, over all channels (1 GiB of values): far above any capture.
constexpr uint64_t kMaxValues = uint64_t(1) << 28;

[[noreturn]] void fail_exr(const std::filesystem::path& path, const std::string& why) {
    throw Error(escaped(path.string()) + ": " + why);
}

// One line of OpenEXR's message (its exceptions may span lines).
std::string first_line(const char* what) {
    std::string s = what;
    const size_t end = s.find('\n');
    return end == std::string::npos ? s : s.substr(0, end);
}

}  // namespace

const ExrChannel* ExrImage::find(std::string_view name) const {
    for (const ExrChannel& c : channels)
        if (c.name == name) return &c;
    return nullptr;
}

void write_exr(const std::filesystem::path& path, const ExrImage& image) {
    const size_t texels = size_t(image.width) * image.height;
    if (texels == 0 || image.channels.empty()) fail_exr(path, "an EXR needs pixels and channels");
    Imf::Header header(int(image.width), int(image.height));
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    for (const ExrChannel& c : image.channels) {
        const size_t size = c.is_uint ? c.uints.size() : c.floats.size();
        if (size != texels) fail_exr(path, "channel " + c.name + " does not hold every pixel");
        const Imf::PixelType type = c.is_uint ? Imf::UINT : Imf::FLOAT;
        header.channels().insert(c.name, Imf::Channel(type));
        // OpenEXR only reads through the slice's pointer when writing.
        char* base = c.is_uint ? reinterpret_cast<char*>(const_cast<uint32_t*>(c.uints.data()))
                               : reinterpret_cast<char*>(const_cast<float*>(c.floats.data()));
        const size_t stride = 4;
        frame.insert(c.name, Imf::Slice(type, base, stride, stride * image.width));
    }
    std::string bytes;
    try {
        Imf::StdOSStream stream;
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(int(image.height));
        }
        bytes = stream.str();
    } catch (const std::exception& e) {
        fail_exr(path, "cannot encode EXR: " + first_line(e.what()));
    }
    write_new_file(path, bytes);
}

ExrImage read_exr(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail_exr(path, "no such file");
    ExrImage image;
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
        if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxValues)
            fail_exr(path,
                     "data window of " + std::to_string(width) + "x" + std::to_string(height));
        image.width = uint32_t(width);
        image.height = uint32_t(height);
        const size_t texels = size_t(width) * size_t(height);
        for (auto it = file.header().channels().begin(); it != file.header().channels().end();
             ++it) {
            ExrChannel c;
            c.name = it.name();
            c.is_uint = it.channel().type == Imf::UINT;
            if (c.is_uint)
                c.uints.resize(texels);
            else
                c.floats.resize(texels);
            image.channels.push_back(std::move(c));
            if (texels * image.channels.size() > kMaxValues)
                fail_exr(path, "more than " + std::to_string(kMaxValues) + " values");
        }
        Imf::FrameBuffer frame;
        for (ExrChannel& c : image.channels) {
            void* data = c.is_uint ? static_cast<void*>(c.uints.data())
                                   : static_cast<void*>(c.floats.data());
            // Slices are addressed by absolute pixel position: Make shifts by the origin.
            frame.insert(c.name, Imf::Slice::Make(c.is_uint ? Imf::UINT : Imf::FLOAT, data, window,
                                                  4, size_t(width) * 4));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        fail_exr(path, "cannot read EXR: " + first_line(e.what()));
    }
    return image;
}

}  // namespace ds::capture
