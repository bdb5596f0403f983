// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves demo: the gallery of built-in cases. Each method contributes its cases from its
// own file demo_<method>.cpp through FAIR_CURVES_DEMO (see registry.h).

#include "gallery.h"
#include "registry.h"

#include <fair/Errors.h>

#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

struct Demo_options {
  std::string out = "demo-out";
  bool inline_svg = false;
  bool list = false;
};

void run_demo(const Demo_options& o) {
#ifdef FAIR_CURVES_NO_GALLERY
  (void)o;
  throw fair::Error("demo: this fair-curves was built without its gallery (cmake -DFAIR_CURVES_GALLERY=OFF); "
                    "rebuild with -DFAIR_CURVES_GALLERY=ON");
#endif
  std::vector<fair_curves::Demo_entry> entries = fair_curves::demo_registry();
  std::stable_sort(entries.begin(), entries.end(), [](const fair_curves::Demo_entry& a, const fair_curves::Demo_entry& b) {
    return a.order != b.order ? a.order < b.order : a.name < b.name;
  });
  if (o.list) {
    for (const fair_curves::Demo_entry& e : entries) std::cout << e.order << ' ' << e.name << '\n';
    return;
  }
  fair_curves::Gallery gallery(
      "fair: demo gallery",
      "Fair interpolating planar curves, computed by the fair library. Each case shows the curve with its control "
      "polygons (grey, dashed), its curvature comb (orange, teeth pointing away from the centre of curvature; the "
      "95th percentile of |curvature| drawn as a tenth of the figure's diagonal, a tooth longer than twice that "
      "clipped and marked red with a dot), the input points (black) and marked points (red), then its signed curvature against arc length (piece joins "
      "dashed), and a table of measured figures.");
  // A failing method must not take the whole gallery down: its error is shown in the page and
  // on stderr, the other sections are written, and the exit code is 1.
  std::vector<std::string> failures;
  for (const fair_curves::Demo_entry& e : entries) {
    try {
      e.add(gallery);
    } catch (const std::exception& x) {
      failures.push_back(e.name + ": " + x.what());
      gallery.add_section("Failed: " + e.name, std::string("This section could not be computed: ") + x.what());
    }
  }
  gallery.write(o.out, o.inline_svg);
  std::cout << "fair-curves demo: wrote " << o.out << "/index.html: " << gallery.section_count() << " sections, "
            << gallery.case_count() << " cases\n";
  if (!failures.empty()) {
    std::string all;
    for (const std::string& f : failures) all += (all.empty() ? "" : "; ") + f;
    throw fair::Error("demo: " + std::to_string(failures.size()) + " section(s) failed: " + all);
  }
}

} // namespace

void register_demo_command(CLI::App& app) {
  auto options = std::make_shared<Demo_options>();
  CLI::App* sub = app.add_subcommand("demo", "Write the demo gallery (index.html with SVG figures) of every method");
  sub->add_option("--out", options->out, "output directory (default demo-out)");
  sub->add_flag("--inline", options->inline_svg, "embed the SVG figures in index.html instead of figures/*.svg");
  sub->add_flag("--list", options->list, "only list the registered demo sections");
  sub->callback([options] { run_demo(*options); });
}
FAIR_CURVES_COMMAND(register_demo_command)
