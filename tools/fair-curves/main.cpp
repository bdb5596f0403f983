// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves: a thin command-line layer over the fair library. Each subcommand registers
// itself from its own file (see registry.h). Exit codes: 0 success, 1 bad input data (a
// missing or malformed file, a degenerate configuration: one message on stderr naming the file
// and line), 2 usage error (unknown option, malformed option value), 3 a result that does not
// solve the problem, its outputs still written (kappa: unsolved; optimal: capped or diverging;
// fair_curves::Exit_code).

#include "registry.h"

#include <fair/Errors.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"fair-curves: fair interpolating planar curves (see doc/fair_curves_program.md)", "fair-curves"};
  app.require_subcommand(1);
  app.fallthrough(false);
  // Registration order across files is unspecified: list the subcommands by name.
  std::vector<fair_curves::Command_entry> commands = fair_curves::command_registry();
  std::sort(commands.begin(), commands.end(),
            [](const fair_curves::Command_entry& a, const fair_curves::Command_entry& b) { return a.name < b.name; });
  for (const fair_curves::Command_entry& c : commands) c.add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const fair_curves::Exit_code& e) {
    return e.code;
  } catch (const fair::Error& e) {
    // A data error that does not name the file it came from (e.g. a degenerate configuration
    // found by the library): prefix the subcommand's input file, so that the one line says
    // which file is at fault.
    std::string what = e.what();
    for (const CLI::App* sub : app.get_subcommands())
      for (const char* name : {"input", "curve"})
        if (const CLI::Option* input = sub->get_option_no_throw(name))
          for (const std::string& file : input->results())
            if (!file.empty() && what.find(file) == std::string::npos) what = file + ": " + what;
    std::cerr << "fair-curves: error: " << what << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fair-curves: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
