// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves serve: the JSON requests of the editor API (doc/editor_api.md) checked and
// translated into the program's own command lines. The methods and their options are read from
// the program's CLI11 subcommands (method_table), so that the API cannot drift from the program.
// A request that is not well formed is refused with a Request_error naming the JSON path of the
// problem (`points[3][1]: not a finite number`); one that is well formed becomes a Child_job: the
// arguments of `fair-curves <command> points.json ... -o -` and the files to write beside it in
// the request's scratch directory. Option values are passed as `--name=value`, never as two
// arguments, so that no value (say "--svg=/etc/x") can be read as an option of its own.

#ifndef FAIR_CURVES_SERVE_REQUEST_H
#define FAIR_CURVES_SERVE_REQUEST_H

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fair_curves {
namespace serve {

/// Caps of a request (doc/editor_api.md, "Caps").
constexpr std::size_t max_points = 20000;
constexpr std::size_t max_text_option = 4096;  ///< characters of one option value
/// Nesting of arrays and objects in a request body: the API needs 6 levels (a metrics request's
/// curve); anything deeper is refused while parsing, before a recursive function (the DOM's
/// dump(), the metrics command's reader, which itself refuses more than 64) can overflow the
/// stack of a connection's thread (review finding 1: 100 000 levels killed the server).
constexpr int max_json_depth = 64;
/// Arrays and objects in a request body. Each costs the parsed DOM ~60-80 bytes of heap for 3
/// bytes of text (`[],`): a 4 MiB body of them was ~300 MB (review finding 7). The largest
/// curve a metrics request can carry within the 4 MiB body cap has far fewer (a 20 000-piece
/// cubic spline: 160 000 in 10.5 MB).
constexpr long long max_json_containers = 300000;
/// Rows of the metrics profile (pieces x samples): the profile is written to a file and read
/// back into the answer; 2000 pieces x 256 samples made a 79 MB answer (review finding 5).
constexpr long long max_profile_rows = 200000;

/// A request refused before anything runs: HTTP `status` (400) and the message of {"error"}.
struct Request_error : std::runtime_error {
  int status;
  explicit Request_error(const std::string& what, int status_ = 400) : std::runtime_error(what), status(status_) {}
};

/// One option of a method as the API offers it.
struct Option_info {
  std::string name;  ///< the long option name without "--"
  std::string type;  ///< "flag", "text", "list" (repeatable) or "file" (rows written to a file)
  std::string help, default_value;
};

/// One method of the API: its name, the subcommand that solves it and the options it takes.
struct Method_info {
  std::string name, command;
  std::vector<Option_info> options;
  const Option_info* find(const std::string& option) const {
    for (const Option_info& o : options)
      if (o.name == option) return &o;
    return nullptr;
  }
};

/// The methods of issue 27 in the order of the API; the classic ones are `spline --method NAME`.
inline const std::vector<std::string>& method_names() {
  static const std::vector<std::string> names{"kappa", "optimal",     "cardinal", "csr",    "cubic",
                                              "catmull-rom", "four-point", "quasi",    "bspline"};
  return names;
}

inline std::string command_of(const std::string& method) {
  return method == "kappa" || method == "optimal" || method == "cardinal" || method == "csr" ? method : "spline";
}

/// Options the server never passes on: they write files (or name the output), or change the exit
/// code the server reads (doc/editor_api.md, "Options"). `plot` writes a file too.
inline bool forbidden_option(const std::string& name) {
  static const std::set<std::string> names{"output", "svg", "dxf", "svg-path", "allow-unsolved", "help", "plot"};
  return names.count(name) > 0;
}

/// Options whose value is a file of number rows: the request gives the rows.
inline bool file_option(const std::string& name) {
  static const std::set<std::string> names{"lambda-file", "tangents", "normals", "corners", "tension"};
  return names.count(name) > 0;
}

/// The API's methods from the subcommands registered in `app` (built as main.cpp builds it).
inline std::vector<Method_info> method_table(const CLI::App& app) {
  std::vector<Method_info> table;
  for (const std::string& name : method_names()) {
    Method_info m;
    m.name = name;
    m.command = command_of(name);
    const CLI::App* sub = app.get_subcommand(m.command);
    for (const CLI::Option* o : sub->get_options()) {
      if (o->get_positional() || o->get_lnames().empty()) continue;
      const std::string option = o->get_lnames().front();
      if (forbidden_option(option) || option == "closed" || (m.command == "spline" && option == "method")) continue;
      Option_info info;
      info.name = option;
      info.type = file_option(option) ? "file"
                  : o->get_expected_max() == 0 ? "flag"
                  : o->get_items_expected_max() > 1 ? "list" : "text";
      info.help = o->get_description();
      info.default_value = o->get_default_str();
      m.options.push_back(info);
    }
    table.push_back(m);
  }
  return table;
}

/// GET /api/methods.
inline nlohmann::json methods_json(const std::vector<Method_info>& table) {
  nlohmann::json methods = nlohmann::json::array();
  for (const Method_info& m : table) {
    nlohmann::json options = nlohmann::json::array();
    for (const Option_info& o : m.options)
      options.push_back({{"name", o.name}, {"type", o.type}, {"help", o.help}, {"default", o.default_value}});
    methods.push_back({{"name", m.name}, {"command", m.command}, {"options", options}});
  }
  return {{"methods", methods}};
}

/// A number as the program reads it back exactly: integers as integers, doubles with 17
/// significant digits.
inline std::string number_text(const nlohmann::json& v) {
  if (v.is_number_integer()) return v.is_number_unsigned() ? std::to_string(v.get<std::uint64_t>())
                                                            : std::to_string(v.get<std::int64_t>());
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v.get<double>());
  return buffer;
}

inline std::string type_name(const nlohmann::json& v) {
  return v.is_null() ? "null" : v.is_boolean() ? "a boolean" : v.is_number() ? "a number" : v.is_string() ? "a string"
         : v.is_array() ? "an array" : "an object";
}

/// A finite number at `path`: 1e400 (read as infinity by the JSON parser) is refused here.
inline double finite_number(const nlohmann::json& v, const std::string& path) {
  if (!v.is_number()) throw Request_error(path + ": expected a number, got " + type_name(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw Request_error(path + ": not a finite number (beyond the range of a double)");
  return x;
}

/// A text option value: a string (no NUL, at most max_text_option characters) or a number.
inline std::string option_text(const nlohmann::json& v, const std::string& path) {
  if (v.is_number()) {
    finite_number(v, path);
    return number_text(v);
  }
  if (!v.is_string()) throw Request_error(path + ": expected a string or a number, got " + type_name(v));
  const std::string& s = v.get_ref<const std::string&>();
  // An empty value would make `--name=` and the command line parser take the next argument as
  // the value (review finding 9): refused, as a value of only white space.
  if (s.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
    throw Request_error(path + ": an empty value (give the option a value, or leave it out)");
  if (s.find('\0') != std::string::npos) throw Request_error(path + ": the text holds a NUL character");
  if (s.size() > max_text_option)
    throw Request_error(path + ": longer than " + std::to_string(max_text_option) + " characters");
  return s;
}

/// A well-formed request of /api/solve or /api/export.
struct Solve_request {
  const Method_info* method = nullptr;
  std::vector<std::array<double, 2>> points;
  bool closed = false;
  nlohmann::json options = nlohmann::json::object();
  std::string session;  ///< empty: none
  std::string format;   ///< /api/export only
};

/// Fewest points of `method` as its command checks them (the commands' check_point_file calls),
/// so that too few points is a 400 like the other malformed requests.
inline std::size_t minimum_points(const Solve_request& r) {
  const std::string& m = r.method->name;
  const bool c = r.closed;
  if (m == "kappa") return 3;
  if (m == "optimal") return c ? 3 : 2;
  if (m == "csr") return c ? 4 : 3;
  if (m == "four-point") return c ? 3 : 4;
  if (m == "cardinal") {
    const auto alpha = r.options.find("alpha");
    if (alpha != r.options.end() && alpha->is_string() && *alpha == "optimal") return c ? 3 : 4;
    return !c && r.options.contains("aux-start") && r.options.contains("aux-end") ? 2 : 3;
  }
  return c ? 3 : 2;  // cubic, catmull-rom, quasi, bspline
}

/// Where a JSON text stops being valid JSON, as a JSON path ("points[3][1]"): a SAX pass that
/// only follows the path, run when parse_body fails, so that its message names the place of a
/// number out of range (1e400) as the other errors do.
class Json_path_tracker : public nlohmann::json_sax<nlohmann::json> {
 public:
  /// The path, its first 200 characters (a body of a million '[' is a path of a million "[0]").
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      if (p.size() > 200) return p.substr(0, 200) + "...";
      if (f.array) {
        if (f.index >= 0) p += "[" + std::to_string(f.index) + "]";
      } else if (!f.key.empty()) p += (p.empty() ? "" : ".") + f.key;
    }
    return p;
  }
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    value();
    frames_.push_back(Frame{false, -1, {}});
    return true;
  }
  bool key(string_t& k) override {
    frames_.back().key = k;
    return true;
  }
  bool end_object() override {
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    value();
    frames_.push_back(Frame{true, -1, {}});
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    // The failing value is the next of an array: name it.
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return false;
  }

 private:
  struct Frame {
    bool array;
    long long index;
    std::string key;
  };
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }
  std::vector<Frame> frames_;
};

/// Parses JSON text (the body), refusing what is not JSON with the parser's message and the
/// path where it stopped; a number beyond the range of a double (1e400) is refused so too.
inline nlohmann::json parse_body(const std::string& body) {
  // The parser itself is iterative; the callback sees the depth of every array and object as it
  // starts (the number of containers around it) and stops the parse beyond max_json_depth.
  long long containers = 0;
  const nlohmann::json::parser_callback_t depth_cap = [&containers](int depth, nlohmann::json::parse_event_t event,
                                                                    nlohmann::json&) {
    if (event == nlohmann::json::parse_event_t::object_start || event == nlohmann::json::parse_event_t::array_start) {
      if (depth >= max_json_depth)
        throw Request_error("the JSON is nested more than " + std::to_string(max_json_depth) +
                            " levels deep (the cap of the API)");
      if (++containers > max_json_containers)
        throw Request_error("the JSON has more than " + std::to_string(max_json_containers) +
                            " arrays and objects (the cap of the API)");
    }
    return true;
  };
  try {
    return nlohmann::json::parse(body, depth_cap);
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();
    const std::size_t bracket = what.find("] ");
    if (what.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos) what = what.substr(bracket + 2);
    Json_path_tracker tracker;
    try {
      nlohmann::json::sax_parse(body, &tracker);
    } catch (...) {
    }
    const std::string path = tracker.path();
    if (e.id == 406) throw Request_error((path.empty() ? std::string() : path + ": ") +
                                         "not a finite number (" + what + ": beyond the range of a double)");
    throw Request_error("malformed JSON" + (path.empty() ? std::string() : " at " + path) + ": " + what);
  }
}

/// Checks every member of a solve (export: `format` too) request.
inline Solve_request parse_solve_request(const nlohmann::json& j, const std::vector<Method_info>& table, bool export_request) {
  if (!j.is_object()) throw Request_error("the request must be a JSON object, got " + type_name(j));
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& k = it.key();
    if (k != "method" && k != "points" && k != "closed" && k != "options" && k != "session" &&
        !(export_request && k == "format"))
      throw Request_error(k + ": unknown member of the request");
  }
  Solve_request r;
  // method
  if (!j.contains("method")) throw Request_error("method: missing");
  const nlohmann::json& method = j["method"];
  if (!method.is_string()) throw Request_error("method: expected a string, got " + type_name(method));
  for (const Method_info& m : table)
    if (m.name == method.get<std::string>()) r.method = &m;
  if (!r.method) {
    std::string names;
    for (const Method_info& m : table) names += (names.empty() ? "" : ", ") + m.name;
    throw Request_error("method: unknown method '" + method.get<std::string>() + "' (one of " + names + ")");
  }
  // closed
  if (j.contains("closed")) {
    if (!j["closed"].is_boolean()) throw Request_error("closed: expected true or false, got " + type_name(j["closed"]));
    r.closed = j["closed"].get<bool>();
  }
  // options
  if (j.contains("options")) {
    const nlohmann::json& options = j["options"];
    if (!options.is_object()) throw Request_error("options: expected an object, got " + type_name(options));
    for (auto it = options.begin(); it != options.end(); ++it) {
      const std::string& name = it.key();
      const std::string path = "options." + name;
      if (forbidden_option(name))
        throw Request_error(path + ": not allowed through the server (it writes a file or changes the exit code)");
      if (name == "closed") throw Request_error(path + ": give \"closed\" as a member of the request");
      const Option_info* info = r.method->find(name);
      if (!info) throw Request_error(path + ": the method " + r.method->name + " has no option '" + name + "'");
      const nlohmann::json& v = it.value();
      if (info->type == "flag") {
        if (!v.is_boolean()) throw Request_error(path + ": expected true or false, got " + type_name(v));
      } else if (info->type == "text") {
        option_text(v, path);
      } else if (info->type == "list") {
        if (v.is_array()) {
          for (std::size_t i = 0; i < v.size(); ++i) option_text(v[i], path + "[" + std::to_string(i) + "]");
        } else option_text(v, path);
      } else {  // file: an array of rows, each a number or an array of numbers
        if (!v.is_array()) throw Request_error(path + ": expected an array of rows, got " + type_name(v));
        for (std::size_t i = 0; i < v.size(); ++i) {
          const std::string row = path + "[" + std::to_string(i) + "]";
          if (v[i].is_array()) {
            if (v[i].empty()) throw Request_error(row + ": an empty row");
            for (std::size_t k = 0; k < v[i].size(); ++k) finite_number(v[i][k], row + "[" + std::to_string(k) + "]");
          } else if (v[i].is_number()) finite_number(v[i], row);
          else throw Request_error(row + ": expected a number or an array of numbers, got " + type_name(v[i]));
        }
      }
    }
    r.options = options;
  }
  // session
  if (j.contains("session")) {
    const nlohmann::json& s = j["session"];
    if (!s.is_string()) throw Request_error("session: expected a string, got " + type_name(s));
    r.session = s.get<std::string>();
    bool ok = !r.session.empty() && r.session.size() <= 64;
    for (const char c : r.session)
      ok = ok && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-');
    if (!ok) throw Request_error("session: expected 1 to 64 characters A-Z a-z 0-9 _ -");
    if (r.method->name != "kappa") throw Request_error("session: sessions are for the method kappa only");
  }
  // format
  if (export_request) {
    if (!j.contains("format")) throw Request_error("format: missing (dxf, svg, svg-path or json)");
    const nlohmann::json& f = j["format"];
    if (!f.is_string() || (f != "dxf" && f != "svg" && f != "svg-path" && f != "json"))
      throw Request_error("format: expected \"dxf\", \"svg\", \"svg-path\" or \"json\"");
    r.format = f.get<std::string>();
  }
  // points (last: the other members' mistakes are named first, and their minimum depends on them)
  if (!j.contains("points")) throw Request_error("points: missing");
  const nlohmann::json& points = j["points"];
  if (!points.is_array()) throw Request_error("points: expected an array of [x, y] pairs, got " + type_name(points));
  if (points.size() > max_points)
    throw Request_error("points: " + std::to_string(points.size()) + " points, more than the cap of " +
                        std::to_string(max_points));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const nlohmann::json& p = points[i];
    const std::string path = "points[" + std::to_string(i) + "]";
    if (!p.is_array() || p.size() != 2) throw Request_error(path + ": expected an [x, y] pair, got " +
                                                            (p.is_array() ? "an array of " + std::to_string(p.size()) : type_name(p)));
    r.points.push_back({finite_number(p[0], path + "[0]"), finite_number(p[1], path + "[1]")});
  }
  const std::size_t minimum = minimum_points(r);
  if (r.points.size() < minimum)
    throw Request_error("points: the method " + r.method->name + (r.closed ? " (closed)" : " (open)") + " needs at least " +
                        std::to_string(minimum) + " points, got " + std::to_string(r.points.size()));
  return r;
}

/// The point file of a request: the program reads back exactly these doubles.
inline std::string points_file_text(const std::vector<std::array<double, 2>>& points) {
  std::string s = "{\"points\": [";
  char buffer[96];
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%s[%.17g, %.17g]", i ? ",\n" : "\n", points[i][0], points[i][1]);
    s += buffer;
  }
  return s + "\n]}\n";
}

/// The rows of a file option, one a line, numbers separated by spaces.
inline std::string rows_file_text(const nlohmann::json& rows) {
  std::string s;
  for (const nlohmann::json& row : rows) {
    if (row.is_array()) {
      for (std::size_t k = 0; k < row.size(); ++k) s += (k ? " " : "") + number_text(row[k]);
    } else s += number_text(row);
    s += "\n";
  }
  return s;
}

/// What to run for a request: the arguments after the program's path (args[0] is its name), the
/// files to write into the scratch directory first, and the file whose contents are the answer
/// (empty: stdout).
struct Child_job {
  std::vector<std::string> args;
  std::vector<std::pair<std::string, std::string>> files;
  std::string answer_file;
};

/// The scratch file of a file option.
inline std::string option_file_name(const std::string& option) { return option + ".txt"; }

/// `fair-curves <command> [--method=NAME] points.json [--closed] <options> -o -` (export: the
/// figure or drawing to a file of the scratch directory instead).
inline Child_job solve_job(const Solve_request& r) {
  Child_job job;
  job.args = {"fair-curves", r.method->command};
  if (r.method->command == "spline") job.args.push_back("--method=" + r.method->name);
  job.args.push_back("points.json");
  job.files.emplace_back("points.json", points_file_text(r.points));
  if (r.closed) job.args.push_back("--closed");
  for (auto it = r.options.begin(); it != r.options.end(); ++it) {
    const Option_info& info = *r.method->find(it.key());
    const std::string flag = "--" + it.key();
    const nlohmann::json& v = it.value();
    if (info.type == "flag") {
      if (v.get<bool>()) job.args.push_back(flag);
    } else if (info.type == "text") {
      job.args.push_back(flag + "=" + option_text(v, it.key()));
    } else if (info.type == "list") {
      if (v.is_array()) {
        for (const nlohmann::json& item : v) job.args.push_back(flag + "=" + option_text(item, it.key()));
      } else job.args.push_back(flag + "=" + option_text(v, it.key()));
    } else {
      job.files.emplace_back(option_file_name(it.key()), rows_file_text(v));
      job.args.push_back(flag + "=" + option_file_name(it.key()));
    }
  }
  if (r.format.empty() || r.format == "json") {
    job.args.push_back("-o");
    job.args.push_back("-");
  } else {
    job.answer_file = r.format == "dxf" ? "curve.dxf" : r.format == "svg" ? "curve.svg" : "curve.txt";
    job.args.push_back("--" + r.format + "=" + job.answer_file);
  }
  return job;
}

/// POST /api/metrics: {"curve": {...}, "samples": k}.
inline Child_job metrics_job(const nlohmann::json& j) {
  if (!j.is_object()) throw Request_error("the request must be a JSON object, got " + type_name(j));
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "curve" && it.key() != "samples") throw Request_error(it.key() + ": unknown member of the request");
  if (!j.contains("curve")) throw Request_error("curve: missing");
  if (!j["curve"].is_object()) throw Request_error("curve: expected a curve object as /api/solve returns it, got " +
                                                   type_name(j["curve"]));
  long long samples = 32;
  if (j.contains("samples")) {
    const nlohmann::json& s = j["samples"];
    if (!s.is_number_integer() || s.get<long long>() < 1 || s.get<long long>() > 256)
      throw Request_error("samples: expected an integer from 1 to 256");
    samples = s.get<long long>();
  }
  const nlohmann::json& curve = j["curve"];
  if (curve.contains("pieces") && curve["pieces"].is_array() &&
      static_cast<long long>(curve["pieces"].size()) * samples > max_profile_rows)
    throw Request_error("curve: " + std::to_string(curve["pieces"].size()) + " pieces x " + std::to_string(samples) +
                        " samples is over the cap of " + std::to_string(max_profile_rows) + " profile rows");
  Child_job job;
  job.args = {"fair-curves", "metrics", "curve.json", "-o", "-", "--profile=profile.csv", "--samples=" + std::to_string(samples)};
  job.files.emplace_back("curve.json", j["curve"].dump());
  return job;
}

} // namespace serve
} // namespace fair_curves

#endif // FAIR_CURVES_SERVE_REQUEST_H
