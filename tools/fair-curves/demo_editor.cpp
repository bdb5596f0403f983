// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The gallery's section of the curve editor (issue 27; doc/editor.md): the screenshot that the
// browser test takes (test/editor/browser_test.mjs), kept as tools/fair-curves/editor/screenshot.png
// and compiled into the program with the page (serve/static_assets.h), so that the gallery of an
// installed program shows it too.

#include "registry.h"
#include "serve/static_assets.h"

#include <fair/io/surface_of_revolution.h>

#include <string>
#include <utility>

namespace {

void add_editor_cases(fair_curves::Gallery& gallery) {
  std::string png;
  if (!fair_curves::serve::find_asset("", "screenshot.png", png)) return;  // a build whose page has no screenshot
  gallery.add_section(
      "The curve editor",
      "fair-curves serve (or bash tools/bootstrap.sh serve) opens a page on http://127.0.0.1:8080/ where a designer "
      "clicks points, drags them and sees every family answer live: the curve, its curvature comb, the kappa(s) plot, "
      "the certified curvature extrema and inflections and the solver's outcome in words. Every curve on the page is "
      "the program's own answer (doc/editor.md, doc/editor_api.md).");
  fair_curves::Gallery_case g;
  g.title = "The editor: a kappa-curve with the optimal curve and the Cardinal spline overlaid";
  g.caption = "A screenshot of the page taken by the browser test (headless chromium): six points, the kappa-curve "
              "(blue) with its comb, control polygon and certified extrema (orange) and inflections (green) on the "
              "curve and in the kappa(s) plot beneath, the optimal curve (red) and the Cardinal spline (violet) "
              "overlaid; the status line is the kappa-curve's report.";
  g.images = {{"the editor", fair::io::png_svg(fair::io::read_png_bytes(png, "screenshot.png"), g.title)}};
  gallery.add_case(std::move(g));
}

} // namespace

FAIR_CURVES_DEMO(90, add_editor_cases)
