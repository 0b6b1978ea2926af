// occlusion: the composition root. The command line and the server are peer
// faces over app/; this file alone knows both and picks one. Every error is
// classified once (app/errors.hpp) and mapped to the contract's exit codes.

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "occlusion/app/errors.hpp"
#include "occlusion/cli/cli.hpp"
#include "occlusion/server/server.hpp"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (!args.empty() && args[0] == "serve") {
      return occlusion::server::run_serve_command({args.begin() + 1, args.end()});
    }
    return occlusion::cli::run(args);
  } catch (const std::exception& e) {
    const occlusion::ErrorKind kind = occlusion::classify(e);
    std::fprintf(
        stderr, "occlusion: %s\n",
        kind == occlusion::ErrorKind::kResource && std::string(e.what()) == "std::bad_alloc"
            ? "out of memory"
            : e.what());
    return occlusion::cli::exit_code(kind);
  } catch (...) {
    std::fprintf(stderr, "occlusion: unknown error\n");
    return 1;
  }
}
