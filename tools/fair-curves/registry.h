// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Self-registration of the subcommands and of the demo gallery's cases, so that each one lives
// in its own file and main.cpp / demo_command.cpp never need editing:
//
//   // <name>_command.cpp
//   void register_<name>_command(CLI::App& app) { auto* sub = app.add_subcommand(...); ... }
//   FAIR_CURVES_COMMAND(register_<name>_command)
//
//   // demo_<method>.cpp
//   void add_<method>_cases(fair_curves::Gallery& gallery) { gallery.add_section(...); ... }
//   FAIR_CURVES_DEMO(30, add_<method>_cases)   // 30: position of the section in the gallery
//
// Every *.cpp of tools/fair-curves/ is compiled into the program (CMake glob), so adding such a
// file is all it takes.

#ifndef FAIR_CURVES_REGISTRY_H
#define FAIR_CURVES_REGISTRY_H

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fair_curves {

// Only a pointer type names it here (Demo_adder): the demo cases include gallery.h; main.cpp and
// serve_command.cpp need not parse it (fair/io/svg.h: 14 s of compile time).
class Gallery;

/// Thrown by a subcommand after it has written its outputs to make the program exit with
/// `code` (main.cpp), e.g. 3 for an unsolved kappa-curve (doc/fair_curves_program.md).
struct Exit_code {
  int code;
};

typedef void (*Command_registrar)(CLI::App&);

struct Command_entry {
  std::string name;
  Command_registrar add;
};
typedef void (*Demo_adder)(fair_curves::Gallery&);

struct Demo_entry {
  int order;
  std::string name;
  Demo_adder add;
};

inline std::vector<Command_entry>& command_registry() {
  static std::vector<Command_entry> registry;
  return registry;
}

inline std::vector<Demo_entry>& demo_registry() {
  static std::vector<Demo_entry> registry;
  return registry;
}

struct Register_command {
  Register_command(const char* name, Command_registrar f) { command_registry().push_back(Command_entry{name, f}); }
};

struct Register_demo {
  Register_demo(int order, const char* name, Demo_adder f) { demo_registry().push_back(Demo_entry{order, name, f}); }
};

} // namespace fair_curves

#define FAIR_CURVES_COMMAND(function) \
  static const ::fair_curves::Register_command fair_curves_command_registration_##function(#function, &function);
#define FAIR_CURVES_DEMO(order, function) \
  static const ::fair_curves::Register_demo fair_curves_demo_registration_##function(order, #function, &function);

#endif // FAIR_CURVES_REGISTRY_H
