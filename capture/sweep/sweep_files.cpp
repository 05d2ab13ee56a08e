#include "capture/sweep/sweep_files.h"

#include <fstream>
#include <sstream>

#include "capture/file_output.h"
#include "capture/report.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace ds::capture::sweep {
namespace {

constexpr uintmax_t kMaxSweepFileBytes = 64ull << 20;

[[noreturn]] void input_fault(const fs::path& path, const std::string& why) {
    throw InputError(escaped(path.string()) + ": " + why);
}

// Names a sweep writes into its folder, and (with ".tmp-") their temporary forms.
bool is_sweep_entry(const fs::directory_entry& entry) {
    const std::string name = entry.path().filename().string();
    for (const char* own : {"manifest.json", "sweep.json", "junit.xml", "report.md", "jobs"})
        if (name == own || name.rfind(std::string(own) + ".tmp-", 0) == 0) return true;
    return false;
}

// What a job writes; with ".tmp-" a child's temporary file or staging folder, left where a
// signal ended the child (the job failed; a new run replaces the folder whole).
bool is_job_entry(const fs::directory_entry& entry) {
    std::error_code ec;
    const std::string name = entry.path().filename().string();
    if (entry.is_symlink(ec)) return false;
    for (const char* own : {"capture", "result.json", "log.txt", "bench.json", "lint.json"})
        if (name.rfind(std::string(own) + ".tmp-", 0) == 0) return true;
    if (name == "capture") return entry.is_directory(ec);
    for (const char* own : {"result.json", "log.txt", "bench.json", "lint.json"})
        if (name == own) return entry.is_regular_file(ec);
    return false;
}

}  // namespace

std::string read_text_file(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) input_fault(path, "no such file");
    if (fs::file_size(path, ec) > kMaxSweepFileBytes) input_fault(path, "larger than 64 MiB");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) input_fault(path, "cannot read");
    return text.str();
}

json read_json_file(const fs::path& path) {
    json doc = json::parse(read_text_file(path), nullptr, false);
    if (doc.is_discarded()) input_fault(path, "not valid JSON");
    return doc;
}

ReplaceableContent job_folder_content() {
    return {is_job_entry, "a sweep job"};
}

void prepare_sweep_folder(const fs::path& dir, const std::string& option) {
    const std::string shown = option + " " + escaped(dir.string());
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(dir, ec);
    if (fs::exists(st)) {
        if (!fs::is_directory(fs::status(dir, ec)))
            throw Error(shown + ": exists and is not a folder");
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
            if (!is_sweep_entry(*it))
                throw Error(shown + ": holds more than a sweep (" +
                            quote(it->path().filename().string()) + "): choose another folder");
        if (ec) throw Error(shown + ": cannot read: " + ec.message());
    }
    fs::create_directories(dir / "jobs", ec);
    if (ec) throw Error(shown + ": cannot create: " + ec.message());
}

void write_sweep_manifest(const fs::path& dir, const SweepManifest& m) {
    json jobs = json::array();
    for (const Job& job : m.jobs) jobs.push_back(job_json(job));
    const json doc = {{"tool", "depthscope"}, {"manifest", m.manifest}, {"jobs", jobs}};
    write_json_atomically("manifest.json", dir / "manifest.json", doc);
}

std::optional<SweepManifest> read_sweep_manifest(const fs::path& dir) {
    const fs::path path = dir / "manifest.json";
    std::error_code ec;
    if (!fs::exists(path, ec)) return std::nullopt;
    const json doc = read_json_file(path);
    if (!doc.is_object() || doc.value("tool", "") != "depthscope" || !doc.contains("jobs") ||
        !doc.at("jobs").is_array() || !doc.contains("manifest"))
        input_fault(path, "not a depthscope sweep's manifest.json");
    SweepManifest m;
    m.manifest = doc.at("manifest");
    for (size_t i = 0; i < doc.at("jobs").size(); ++i)
        m.jobs.push_back(job_from_json(doc.at("jobs").at(i),
                                       path.string() + ": jobs[" + std::to_string(i) + "]"));
    return m;
}

fs::path job_dir(const fs::path& dir, const std::string& id) {
    return dir / "jobs" / id;
}

std::optional<json> read_job_result(const fs::path& dir, const std::string& id) {
    const fs::path path = job_dir(dir, id) / "result.json";
    std::error_code ec;
    if (!fs::exists(path, ec)) return std::nullopt;
    json result = read_json_file(path);
    if (!result.is_object() || result.value("id", "") != id)
        input_fault(path, "not the result of job " + id);
    return result;
}

std::string copy_job(const fs::path& from, const fs::path& to, const std::string& id) {
    OutputDir out(job_dir(to, id), job_folder_content());
    const fs::path source = job_dir(from, id);
    std::error_code ec;
    fs::copy(source, out.staging_dir(),
             fs::copy_options::recursive | fs::copy_options::create_hard_links, ec);
    if (ec) {  // another file system: copy the bytes
        fs::remove_all(out.staging_dir(), ec);
        fs::create_directory(out.staging_dir(), ec);
        fs::copy(source, out.staging_dir(), fs::copy_options::recursive, ec);
    }
    if (ec)
        throw Error(escaped(source.string()) + ": cannot copy to " +
                    escaped(job_dir(to, id).string()) + ": " + ec.message());
    return out.commit();
}

bool same_folder(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::equivalent(a, b, ec) && !ec;
}

}  // namespace ds::capture::sweep
