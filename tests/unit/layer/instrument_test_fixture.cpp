#include "instrument_test_fixture.h"

#include <spirv-tools/libspirv.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <utility>

namespace ds::layer::testing {

std::vector<Op> split(std::span<const uint32_t> spirv) {
    std::vector<Op> out;
    for (size_t at = 5; at < spirv.size();) {
        const uint32_t n = spirv[at] >> spv::WordCountShift;
        if (n == 0 || at + n > spirv.size()) {
            ADD_FAILURE() << "truncated instruction at word " << at;
            break;
        }
        out.push_back({spv::Op(spirv[at] & spv::OpCodeMask), spirv.subspan(at + 1, n - 1)});
        at += n;
    }
    return out;
}

size_t count(std::span<const uint32_t> spirv, spv::Op op) {
    const std::vector<Op> ops = split(spirv);
    return size_t(std::count_if(ops.begin(), ops.end(), [&](const Op& o) { return o.op == op; }));
}

size_t count_decorations(std::span<const uint32_t> spirv, spv::Decoration decoration,
                         uint32_t value) {
    size_t n = 0;
    for (const Op& o : split(spirv))
        n += o.op == spv::OpDecorate && o.operands.size() > 2 && o.operands[1] == decoration &&
             o.operands[2] == value;
    return n;
}

std::vector<uint32_t> interface_of(std::span<const uint32_t> spirv, const std::string& entry) {
    for (const Op& o : split(spirv)) {
        if (o.op != spv::OpEntryPoint || o.operands[0] != spv::ExecutionModelFragment) continue;
        const char* name = reinterpret_cast<const char*>(o.operands.data() + 2);
        if (entry != name) continue;
        const size_t start = 2 + entry.size() / 4 + 1;
        return {o.operands.begin() + std::ptrdiff_t(start), o.operands.end()};
    }
    ADD_FAILURE() << "no Fragment entry point " << entry;
    return {};
}

std::vector<uint32_t> bindings_in_set(std::span<const uint32_t> spirv, uint32_t set) {
    std::vector<uint32_t> in_set;
    std::vector<std::pair<uint32_t, uint32_t>> bindings;  // id, binding
    for (const Op& o : split(spirv)) {
        if (o.op != spv::OpDecorate) continue;
        if (o.operands[1] == spv::DecorationDescriptorSet && o.operands[2] == set)
            in_set.push_back(o.operands[0]);
        if (o.operands[1] == spv::DecorationBinding)
            bindings.emplace_back(o.operands[0], o.operands[2]);
    }
    std::vector<uint32_t> out;
    for (auto [id, binding] : bindings)
        if (std::find(in_set.begin(), in_set.end(), id) != in_set.end()) out.push_back(binding);
    std::sort(out.begin(), out.end());
    return out;
}

namespace {

spv_target_env env_of(uint32_t version) {
    switch (version) {
        case 0x00010000:
            return SPV_ENV_VULKAN_1_0;
        case 0x00010400:
            return SPV_ENV_VULKAN_1_1_SPIRV_1_4;
        case 0x00010500:
            return SPV_ENV_VULKAN_1_2;
        case 0x00010600:
            return SPV_ENV_VULKAN_1_3;
        default:
            return SPV_ENV_VULKAN_1_1;  // SPIR-V 1.1 to 1.3
    }
}

std::vector<uint32_t> read_words(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
    std::vector<uint32_t> words(bytes.size() / 4);
    std::copy_n(bytes.data(), words.size() * 4, reinterpret_cast<char*>(words.data()));
    return words;
}

}  // namespace

std::string validation_errors(std::span<const uint32_t> spirv) {
    if (spirv.size() < 5) return "not a module";
    spvtools::SpirvTools tools(env_of(spirv[1]));
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&,
                                 const char* m) { messages += std::string(m) + "\n"; });
    if (tools.Validate(spirv.data(), spirv.size())) return "";
    std::string text;
    tools.Disassemble(spirv.data(), spirv.size(), &text,
                      SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT);
    return messages + text;
}

std::vector<uint32_t> assemble(const std::string& text, uint32_t version) {
    const spv_target_env env = version == 0x10300   ? SPV_ENV_UNIVERSAL_1_3
                               : version == 0x10500 ? SPV_ENV_UNIVERSAL_1_5
                                                    : SPV_ENV_UNIVERSAL_1_6;
    spvtools::SpirvTools tools(env);
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&,
                                 const char* m) { messages += std::string(m) + "\n"; });
    std::vector<uint32_t> out;
    EXPECT_TRUE(tools.Assemble(text, &out, SPV_TEXT_TO_BINARY_OPTION_PRESERVE_NUMERIC_IDS))
        << messages;
    return out;
}

std::vector<uint32_t> InstrumentTest::compile(const std::string& source, ds::shader::Stage stage) {
    const std::string name = stage == ds::shader::Stage::Fragment ? "t.frag" : "t.vert";
    write(name, source);
    return ds::shader::Compiler(root(), cache()).compile(name, stage).spirv;
}

std::vector<uint32_t> InstrumentTest::compile_for(const std::string& source, const std::string& env,
                                                  const std::string& args,
                                                  const std::string& file) {
    write(file, source);
    const auto out = dir_ / "t.spv", log = dir_ / "glslang.log";
    const std::string command = "glslangValidator -V --target-env " + env + " " + args + " -o '" +
                                out.string() + "' '" + (root() / file).string() + "' > '" +
                                log.string() + "' 2>&1";
    if (std::system(command.c_str()) != 0) {
        std::ifstream in(log);
        ADD_FAILURE() << command << "\n" << std::string((std::istreambuf_iterator<char>(in)), {});
        return {};
    }
    return read_words(out);
}

InstrumentResult InstrumentTest::instrument(std::span<const uint32_t> spirv,
                                            const CounterBindings& b, const std::string& entry) {
    EXPECT_EQ(validation_errors(spirv), "") << "the input is not valid";
    InstrumentResult r = instrument_fragment(spirv, entry, b);
    EXPECT_EQ(validation_errors(r.spirv), "");
    dump(r.spirv);
    return r;
}

void InstrumentTest::dump(std::span<const uint32_t> spirv) {
    const char* dir = std::getenv("DS_INSTRUMENT_DUMP");
    if (!dir) return;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::create_directories(dir);
    std::ofstream(
        std::filesystem::path(dir) / (std::string(info->test_suite_name()) + "." + info->name() +
                                      "." + std::to_string(dumped_++) + ".spv"),
        std::ios::binary)
        .write(reinterpret_cast<const char*>(spirv.data()), std::streamsize(spirv.size() * 4));
}

std::string InstrumentTest::fragment(const std::string& decl, const std::string& body) {
    return "#version 460\n" + decl +
           "\nlayout(location = 0) out vec4 color;\n"
           "layout(location = 0) in vec2 uv;\n"
           "void main() {\n  color = vec4(uv, 0.0, 1.0);\n" +
           body + "\n}\n";
}

}  // namespace ds::layer::testing
