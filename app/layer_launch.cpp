#include "app/layer_launch.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

extern char** environ;

namespace ds::app {

namespace {

constexpr const char* kLayerName = "VK_LAYER_DEPTHSCOPE_diagnostics";

// `name=value` for every variable of this process, with `env` set over them and the loader's
// two lists extended.
std::vector<std::string> child_environment(const std::map<std::string, std::string>& env) {
    std::map<std::string, std::string> vars;
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e;
        const auto eq = entry.find('=');
        if (eq != std::string::npos) vars[entry.substr(0, eq)] = entry.substr(eq + 1);
    }
    const auto prepend = [&vars](const std::string& name, const std::string& value) {
        const std::string old = vars.count(name) ? vars[name] : "";
        vars[name] = old.empty() ? value : value + ":" + old;
    };
    // VK_LAYER_PATH, where set, replaces the loader's search (and the Debian 1.3.239 loader
    // then ignores VK_ADD_LAYER_PATH): the layer's folder joins whichever is in use.
    const bool replaced = vars.count("VK_LAYER_PATH") && !vars["VK_LAYER_PATH"].empty();
    prepend(replaced ? "VK_LAYER_PATH" : "VK_ADD_LAYER_PATH", layer_manifest_dir());
    // Layers the application enables itself (validation) sit below it and see its calls.
    prepend("VK_INSTANCE_LAYERS", kLayerName);
    for (const auto& [k, v] : env) vars[k] = v;
    std::vector<std::string> out;
    for (const auto& [k, v] : vars) out.push_back(k + "=" + v);
    return out;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (std::string& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

}  // namespace

std::string layer_manifest_dir() {
    const char* override_dir = std::getenv("DEPTHSCOPE_LAYER_PATH");
    const std::filesystem::path dir = override_dir ? override_dir : DS_LAYER_MANIFEST_DIR;
    if (!std::filesystem::exists(dir / "VkLayer_depthscope.json"))
        throw Error("the layer's manifest is not in " + quote(dir.string()) +
                    " (build the target VkLayer_depthscope, or set DEPTHSCOPE_LAYER_PATH)");
    return dir.string();
}

int run_with_layer(const std::vector<std::string>& argv,
                   const std::map<std::string, std::string>& env) {
    std::vector<std::string> args = argv;
    std::vector<std::string> vars = child_environment(env);
    std::vector<char*> arg_ptrs = pointers(args), env_ptrs = pointers(vars);
    pid_t pid = 0;
    const int err =
        posix_spawnp(&pid, args[0].c_str(), nullptr, nullptr, arg_ptrs.data(), env_ptrs.data());
    if (err == ENOENT) throw Error(quote(args[0]) + ": not found");
    if (err != 0) throw Error(quote(args[0]) + ": cannot start: " + std::strerror(err));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            throw Error(std::string("waiting for the application: ") + std::strerror(errno));
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return WEXITSTATUS(status);
}

}  // namespace ds::app
