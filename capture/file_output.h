#pragma once
// Files written whole or not at all (DESIGN decision 8). Every output file goes through here:
// a capture's final.png and report.json (into its staging folder), and the files named on the
// command line (bench --json, pixel --json; --trace next), which are checked before any work
// and replace only a regular file or a new name.
#include <filesystem>
#include <string>
#include <string_view>

namespace ds::capture {

// Every byte of `data` into the open descriptor `fd` (write(2) until done, EINTR retried). A
// short write is an error: throws ds::Error "PATH: cannot write: " + the reason (EFBIG "File
// too large" under a file-size limit, ENOSPC, EIO ...).
void write_all(int fd, std::string_view data, const std::filesystem::path& path);

// `data` as a new file at `path` (never over an existing one), written to its last byte and
// closed with the result checked. On failure the file is removed and ds::Error thrown.
void write_new_file(const std::filesystem::path& path, std::string_view data);

// Before any work: `path`, named by `option` ("--json"), must be a regular file or a new name
// in an existing folder. A directory, device node, FIFO, socket or symbolic link there is
// refused (renaming over it would replace the node, or fail only after the work). Throws
// ds::Error "OPTION PATH: WHY".
void check_output_file(std::string_view option, const std::filesystem::path& path);

// `data` to `path` through a temporary file beside it (removed on failure and on a signal),
// renamed onto it only while `path` is still a regular file or absent. Throws ds::Error.
void write_file_atomically(std::string_view option, const std::filesystem::path& path,
                           std::string_view data);

}  // namespace ds::capture
