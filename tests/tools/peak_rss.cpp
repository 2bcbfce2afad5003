// peak_rss OUT PROGRAM ARGS...: runs PROGRAM with its output dropped and
// writes "<exit code> <peak RSS in KiB>" to OUT.
//
// Why a program of its own: Linux keeps the peak RSS of the memory a process
// had before exec() in its ru_maxrss, so a child forked straight from a large
// test process (an ASan test binary holds some 100 MiB) reports at least
// that. Forked from this small process instead, the child's figure is its
// own. Built without sanitizers so that it stays small.
#include <cstdio>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: peak_rss OUT PROGRAM [ARGS...]\n");
    return 2;
  }
  const pid_t pid = fork();
  if (pid < 0) return 2;
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execv(argv[2], argv + 2);
    _exit(127);
  }
  int status = 0;
  struct rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid) return 2;
  std::FILE* out = std::fopen(argv[1], "w");
  if (out == nullptr) return 2;
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::fprintf(out, "%d %ld\n", code, ru.ru_maxrss);
  return std::fclose(out) == 0 ? 0 : 2;
}
