// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves serve: the kappa sessions, the one path of the server that solves in process
// (doc/editor_api.md, "kappa sessions"). A session keeps the last fair::Kappa_curve_2 it solved;
// when the next request of the session has the same number of points, the same `closed` and
// options, and exactly one point moved, the curve is re-solved warm by move_point (the library's
// interactive path, a fraction of a millisecond per drag step) instead of afresh. The curve is
// solved, checked and written by the kappa command's own code (kappa_session.h, defined in
// kappa_command.cpp) from the text of the point file the command would read, so the answer is the
// command's JSON of that curve.
//
// Anything the in-process path does not handle exactly as the command (an option other than
// weights, tension, clamp and max-iterations; any error) returns no answer, and the caller runs
// the command in a child process instead, so that errors are the command's own messages.
//
// Locking: the store's mutex guards the map and the LRU order only; each session has its own
// mutex, held during its solve, so that sessions solve in parallel and the requests of one
// session one after another.

#ifndef FAIR_CURVES_SERVE_KAPPA_SESSIONS_H
#define FAIR_CURVES_SERVE_KAPPA_SESSIONS_H

#include "../kappa_session.h"
#include "child_process.h"
#include "request.h"

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace fair_curves {
namespace serve {

constexpr std::size_t max_sessions = 64;            ///< least recently used evicted beyond
constexpr std::size_t max_session_points = 2000;    ///< more: solved by the child, no session
/// The kappa command's default cap on the Jacobians of a solve. A session solve runs in the
/// server's own process, without the child's time and memory caps, so a request asking for more
/// is solved by the child instead (review finding 4): an in-process solve is bounded by
/// max_session_points points x this many Jacobians.
constexpr double max_session_iterations = 200;

/// The answer of the in-process path.
struct Kappa_session_answer {
  bool answered = false;  ///< false: run the command in a child instead
  bool warm = false;      ///< solved by move_point
  bool busy = false;      ///< a fresh solve found no free solve slot before the deadline
  std::string json;
};

class Kappa_sessions {
 public:
  /// Whether a request is for this path: kappa, a session, at most max_session_points points,
  /// and only the options handled here.
  static bool handles(const Solve_request& r) {
    if (r.method->name != "kappa" || r.session.empty() || r.points.size() > max_session_points) return false;
    for (auto it = r.options.begin(); it != r.options.end(); ++it) {
      if (it.key() != "weights" && it.key() != "tension" && it.key() != "clamp" && it.key() != "max-iterations")
        return false;
      if (it.key() == "max-iterations") {
        // Above the default cap (or not a number): the child, with its caps, and its message.
        const nlohmann::json& v = it.value();
        double n = 0;
        if (v.is_number()) n = v.get<double>();
        else if (v.is_string()) {
          const std::string& t = v.get_ref<const std::string&>();
          char* end = nullptr;
          n = std::strtod(t.c_str(), &end);
          if (t.empty() || *end != '\0') return false;
        } else return false;
        if (!(n <= max_session_iterations)) return false;
      }
    }
    return true;
  }

  /// Solves a session request; a fresh (not warm) solve first takes one of `slots` (waiting until
  /// `deadline`), since it may take seconds of a core (2000 points: 1.4-1.9 s).
  Kappa_session_answer solve(const Solve_request& r, Solve_slots& slots, std::chrono::steady_clock::time_point deadline) {
    Kappa_session_answer a;
    if (!handles(r)) return a;
    // The command's options and point file, exactly as the child would get them.
    kappa::Kappa_command_options o;
    o.input = "points.json";
    o.json_out = "-";
    o.closed = r.closed;
    std::string tension_text;
    for (auto it = r.options.begin(); it != r.options.end(); ++it) {
      if (it.key() == "weights") o.weights = option_text(it.value(), it.key());
      if (it.key() == "clamp") {
        o.clamp = option_text(it.value(), it.key());
        o.clamp_given = true;
      }
      if (it.key() == "max-iterations") o.max_iterations = option_text(it.value(), it.key());
      if (it.key() == "tension") {
        o.tension_file = option_file_name("tension");
        tension_text = rows_file_text(it.value());
      }
    }
    const std::string points = points_file_text(r.points);
    const std::string key = (r.closed ? "closed " : "open ") + r.options.dump();
    const std::shared_ptr<Session> s = session(r.session);
    std::lock_guard<std::mutex> lock(s->mutex);
    try {
      std::size_t moved = 0, differing = 0;
      const bool same = s->curve && s->key == key && s->points.size() == r.points.size();
      if (same)
        for (std::size_t i = 0; i < r.points.size(); ++i)
          if (s->points[i] != r.points[i]) {
            moved = i;
            ++differing;
          }
      if (same && differing == 1) {
        s->curve->move_point(points, moved);  // strong guarantee: unchanged if it throws
        a.warm = true;
      } else {
        s->curve.reset();
        const Solve_slot slot(slots, deadline);
        if (!slot) {
          a.busy = true;
          return a;
        }
        s->curve.reset(new kappa::Kappa_session_curve(o, points, tension_text));
      }
      s->points = r.points;
      s->key = key;
      a.json = s->curve->json();
      a.answered = true;
    } catch (...) {
      s->curve.reset();  // forget the session's curve; the child answers in the command's words
      a = Kappa_session_answer();
    }
    return a;
  }

  std::size_t size() {
    std::lock_guard<std::mutex> lock(mutex_);
    return sessions_.size();
  }

 private:
  struct Session {
    std::mutex mutex;
    std::unique_ptr<kappa::Kappa_session_curve> curve;
    std::vector<std::array<double, 2>> points;
    std::string key;  ///< closed and options of the curve
    std::list<std::string>::iterator lru;
  };

  /// The session `id`, made if new, now the most recently used; the least recently used beyond
  /// max_sessions forgotten (a request still solving in it keeps it alive by its shared_ptr).
  std::shared_ptr<Session> session(const std::string& id) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = sessions_.find(id);
    if (it != sessions_.end()) {
      order_.erase(it->second->lru);
    } else {
      it = sessions_.emplace(id, std::make_shared<Session>()).first;
      if (sessions_.size() > max_sessions) {
        sessions_.erase(order_.back());
        order_.pop_back();
      }
    }
    order_.push_front(id);
    it->second->lru = order_.begin();
    return it->second;
  }

  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<Session>> sessions_;
  std::list<std::string> order_;  ///< most recently used first
};

} // namespace serve
} // namespace fair_curves

#endif // FAIR_CURVES_SERVE_KAPPA_SESSIONS_H
