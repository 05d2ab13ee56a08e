#include "renderer/shader/glslang_backend.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>

#include <algorithm>
#include <memory>
#include <utility>

#include "renderer/shader/diagnostics.h"

namespace ds::shader {

namespace fs = std::filesystem;

namespace {

// glslang keeps process-wide tables; a function-local static makes the set-up thread-safe and
// tears it down at exit.
void ensure_glslang_process() {
    struct Process {
        Process() { glslang::InitializeProcess(); }
        ~Process() { glslang::FinalizeProcess(); }
    };
    static Process process;
}

EShLanguage to_glslang(Stage stage) {
    switch (stage) {
        case Stage::Vertex:
            return EShLangVertex;
        case Stage::Fragment:
            return EShLangFragment;
        case Stage::Compute:
            return EShLangCompute;
    }
    return EShLangVertex;
}

// Serves `#include` from the SourceTree. glslang reports every location inside an include by
// the headerName we return, so returning root-relative names gives "common/x.glsl:LINE".
class Includer : public glslang::TShader::Includer {
  public:
    Includer(SourceTree& tree, std::string main_name) : tree_(tree) {
        stack_.push_back(std::move(main_name));
    }

    // glslang asks "local" first for "..." and falls back to "system" when that fails; we do
    // the whole "..." search here and hand any error to the system call that follows.
    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
        pending_error_.clear();
        return include({header, /*system=*/false}, includer, depth, pending_error_);
    }

    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        std::string message = std::exchange(pending_error_, {});
        if (message.empty()) {
            if (IncludeResult* result =
                    include({header, /*system=*/true}, includer, depth, message)) {
                return result;
            }
        }
        // glslang prints this as "'#include' : MESSAGE for header name: HEADER".
        messages_.push_back(std::make_unique<std::string>(std::move(message)));
        return new IncludeResult("", messages_.back()->data(), messages_.back()->size(), nullptr);
    }

    void releaseInclude(IncludeResult* result) override { delete result; }

    const std::vector<fs::path>& files() const { return files_; }

  private:
    // Returns nullptr and sets `error` when the include cannot be served.
    IncludeResult* include(const IncludeDirective& directive, const char* includer, size_t depth,
                           std::string& error) {
        // depth = open includes + 1, so stack_[0, depth) is the chain that reached this line.
        stack_.resize(std::min(stack_.size(), depth));
        const auto resolved = tree_.resolve(directive, includer ? includer : stack_.back());
        const std::string* text = resolved ? tree_.read(*resolved) : nullptr;
        if (text == nullptr) {
            error = "cannot open include";
            return nullptr;
        }
        const std::string name = tree_.name_of(*resolved);
        if (std::find(stack_.begin(), stack_.end(), name) != stack_.end()) {
            error = "include cycle (";
            for (const std::string& open : stack_) error += open + " -> ";
            error += name + ")";
            return nullptr;
        }
        stack_.push_back(name);
        if (std::find(files_.begin(), files_.end(), *resolved) == files_.end()) {
            files_.push_back(*resolved);
        }
        return new IncludeResult(name, text->data(), text->size(), nullptr);
    }

    SourceTree& tree_;
    std::vector<std::string> stack_;
    std::vector<fs::path> files_;
    std::string pending_error_;
    std::vector<std::unique_ptr<std::string>> messages_;  // must outlive the parse
};

constexpr auto kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
constexpr int kDefaultVersion = 460;  // only used by a shader without #version

std::vector<uint32_t> emit_spirv(glslang::TProgram& program, EShLanguage lang) {
    glslang::SpvOptions options;
    options.generateDebugInfo = false;
    options.disableOptimizer = true;  // the driver optimises; keeps compiles fast for reload
    options.validate = false;
    spv::SpvBuildLogger logger;
    std::vector<uint32_t> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &logger, &options);
    return spirv;
}

}  // namespace

std::string glslang_version_tag() {
    return "ds-spirv-2/glslang-" + std::to_string(GLSLANG_VERSION_MAJOR) + "." +
           std::to_string(GLSLANG_VERSION_MINOR) + "." + std::to_string(GLSLANG_VERSION_PATCH) +
           GLSLANG_VERSION_FLAVOR + "/vulkan1.2/spirv1.5/noopt";
}

GlslangOutput run_glslang(SourceTree& tree, const fs::path& main_file, Stage stage,
                          const std::string& preamble) {
    ensure_glslang_process();
    const std::string main_name = tree.name_of(main_file);
    const std::string* text = tree.read(main_file);
    if (text == nullptr) throw ShaderError(main_name + ": cannot open");

    const EShLanguage lang = to_glslang(stage);
    glslang::TShader shader(lang);
    const char* strings[] = {text->data()};
    const int lengths[] = {static_cast<int>(text->size())};
    const char* names[] = {main_name.c_str()};
    shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    // SPIR-V 1.5: valid on the Vulkan 1.2 devices we accept (lavapipe under RenderDoc), and
    // it states compute workgroup sizes as literals (1.6 uses LocalSizeId, which needs
    // maintenance4).
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);

    Includer includer(tree, main_name);
    GlslangOutput out;
    const bool parsed = shader.parse(GetDefaultResources(), kDefaultVersion, ENoProfile,
                                     /*forceDefaultVersionAndProfile=*/false,
                                     /*forwardCompatible=*/false, kMessages, includer);
    out.includes = includer.files();
    if (!parsed) throw ShaderError(format_info_log(shader.getInfoLog(), main_name), out.includes);

    // Declared after the shader: glslang requires the program to die first.
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(kMessages)) {
        throw ShaderError(format_info_log(program.getInfoLog(), main_name), out.includes);
    }
    out.spirv = emit_spirv(program, lang);
    if (out.spirv.empty()) throw ShaderError(main_name + ": SPIR-V generation failed");
    return out;
}

}  // namespace ds::shader
