#include "app/sweep_child.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {

namespace {

// In the forked child: never returns.
[[noreturn]] void exec_child(pid_t parent, int log_fd, std::vector<char*>& argv) {
    // The sweep's death (SIGKILL from a scheduler, OOM) ends the job too.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    // The sweep's own handlers (signal_cleanup.h) are reset to the default by exec.
    ::execv("/proc/self/exe", argv.data());
    const char* why = std::strerror(errno);
    (void)!::write(STDERR_FILENO, "depthscope: error: cannot start the job: ", 41);
    (void)!::write(STDERR_FILENO, why, std::strlen(why));
    (void)!::write(STDERR_FILENO, "\n", 1);
    ::_exit(127);
}

}  // namespace

capture::sweep::ChildExit run_child(const std::vector<std::string>& args,
                                    const std::filesystem::path& log) {
    const int log_fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log_fd < 0) throw Error(escaped(log.string()) + ": cannot create: " + std::strerror(errno));
    std::vector<std::string> words = {"depthscope"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const pid_t parent = ::getpid();
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) exec_child(parent, log_fd, argv);
    const int fork_error = errno;
    ::close(log_fd);
    if (pid < 0) throw Error(std::string("cannot start a job: fork: ") + std::strerror(fork_error));
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw Error(std::string("waitpid: ") + std::strerror(errno));
    capture::sweep::ChildExit exit;
    exit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (WIFSIGNALED(status))
        exit.signal = WTERMSIG(status);
    else
        exit.exit_code = WEXITSTATUS(status);
    return exit;
}

}  // namespace ds::app
