// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair_curves::Gallery (the page of `fair-curves demo`): an HTML page (index.html) of curve figures, in sections, one <figure>
// per case with its SVG images, a caption, a table of measured figures (name / value) and,
// optionally, a table of several columns (one row per method, say).
// The SVG images are written next to index.html (DIR/figures/<case>-<k>.svg) and linked, or
// inlined into the page. The page is self-contained: no scripts, no external style sheets.

#ifndef FAIR_CURVES_GALLERY_H
#define FAIR_CURVES_GALLERY_H

#include <fair/Errors.h>
#include <fair/io/svg.h>

#include <cctype>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fair_curves {

/// One case of the gallery.
struct Gallery_case {
  std::string title;
  std::string caption;  ///< plain text
  /// The images: (alt text, SVG text), shown side by side / stacked.
  std::vector<std::pair<std::string, std::string>> images;
  /// The measured figures: (name, value) rows of the case's table.
  std::vector<std::pair<std::string, std::string>> measurements;
  /// A table of several columns (e.g. one row per method): the first row is the header; empty:
  /// none. Shown after the measurements.
  std::vector<std::vector<std::string>> table;
};

class Gallery {
public:
  explicit Gallery(std::string title, std::string introduction = std::string())
    : title_(std::move(title)), introduction_(std::move(introduction)) {}

  /// Starts a new section; the cases added next belong to it.
  void add_section(const std::string& title, const std::string& introduction = std::string()) {
    sections_.push_back(Section{title, introduction, {}});
  }

  /// Adds a case to the current section (an untitled one is started if there is none).
  void add_case(Gallery_case c) {
    if (sections_.empty()) add_section(std::string());
    sections_.back().cases.push_back(std::move(c));
  }

  std::size_t section_count() const { return sections_.size(); }
  std::size_t case_count() const {
    std::size_t n = 0;
    for (const Section& s : sections_) n += s.cases.size();
    return n;
  }

  /// The HTML page. With inline_svg the images are embedded; otherwise they are referenced
  /// as figures/<id>.svg (see image_file_names()).
  std::string html(bool inline_svg) const {
    using fair::io::xml_escape;
    std::string out;
    out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
           xml_escape(title_) + "</title>\n<style>\n"
           "body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}\n"
           "figure.case{border:1px solid #ddd;border-radius:6px;padding:1em;margin:1.5em 0}\n"
           "figure.case img,figure.case svg{max-width:100%;height:auto;display:block;margin:0.5em 0}\n"
           "figcaption{margin:0.5em 0;line-height:1.4}\n"
           "table{border-collapse:collapse;font-size:0.9em}\n"
           "td,th{border:1px solid #ccc;padding:0.25em 0.6em;text-align:left}\n"
           "td.value{font-family:monospace}\n"
           "nav li{margin:0.2em 0}\n"
           "</style>\n</head>\n<body>\n";
    out += "<h1>" + xml_escape(title_) + "</h1>\n";
    if (!introduction_.empty()) out += "<p>" + xml_escape(introduction_) + "</p>\n";
    if (sections_.size() > 1) {
      out += "<nav><ul>\n";
      for (std::size_t i = 0; i < sections_.size(); ++i)
        out += "<li><a href=\"#section-" + std::to_string(i + 1) + "\">" +
               xml_escape(sections_[i].title) + "</a></li>\n";
      out += "</ul></nav>\n";
    }
    std::size_t number = 0;
    const std::vector<std::string> names = image_file_names();
    std::size_t image = 0;
    for (std::size_t i = 0; i < sections_.size(); ++i) {
      const Section& s = sections_[i];
      out += "<section id=\"section-" + std::to_string(i + 1) + "\">\n";
      if (!s.title.empty()) out += "<h2>" + xml_escape(s.title) + "</h2>\n";
      if (!s.introduction.empty()) out += "<p>" + xml_escape(s.introduction) + "</p>\n";
      for (const Gallery_case& c : s.cases) {
        ++number;
        out += "<figure class=\"case\" id=\"case-" + std::to_string(number) + "\">\n";
        for (const auto& img : c.images) {
          if (inline_svg) out += svg_body(img.second);
          else
            out += "<img src=\"figures/" + xml_escape(names[image]) + "\" alt=\"" +
                   xml_escape(img.first) + "\">\n";
          ++image;
        }
        out += "<figcaption><strong>" + std::to_string(number) + ". " + xml_escape(c.title) +
               "</strong>";
        if (!c.caption.empty()) out += " &mdash; " + xml_escape(c.caption);
        out += "</figcaption>\n";
        if (!c.measurements.empty()) {
          out += "<table>\n<tr><th>measured</th><th>value</th></tr>\n";
          for (const auto& m : c.measurements)
            out += "<tr><td>" + xml_escape(m.first) + "</td><td class=\"value\">" +
                   xml_escape(m.second) + "</td></tr>\n";
          out += "</table>\n";
        }
        if (!c.table.empty()) {
          out += "<table>\n";
          for (std::size_t r = 0; r < c.table.size(); ++r) {
            out += "<tr>";
            for (const std::string& cell : c.table[r])
              out += (r == 0 ? "<th>" : "<td class=\"value\">") + xml_escape(cell) + (r == 0 ? "</th>" : "</td>");
            out += "</tr>\n";
          }
          out += "</table>\n";
        }
        out += "</figure>\n";
      }
      out += "</section>\n";
    }
    out += "</body>\n</html>\n";
    return out;
  }

  /// The file names (under figures/) of every image, in page order: case-<n>-<k>-<slug>.svg.
  std::vector<std::string> image_file_names() const {
    std::vector<std::string> names;
    std::size_t number = 0;
    for (const Section& s : sections_)
      for (const Gallery_case& c : s.cases) {
        ++number;
        for (std::size_t k = 0; k < c.images.size(); ++k)
          names.push_back("case-" + std::to_string(number) + "-" + std::to_string(k + 1) + "-" +
                          slug(c.images[k].first) + ".svg");
      }
    return names;
  }

  /// Writes `directory`/index.html and, unless inline_svg, `directory`/figures/*.svg. Creates
  /// the directories. Throws fair::Error if a file cannot be written.
  void write(const std::string& directory, bool inline_svg = false) const {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(fs::path(directory) / "figures", ec);
    if (ec) throw fair::Error("fair_curves::Gallery: cannot create " + directory + ": " + ec.message());
    if (!inline_svg) {
      const std::vector<std::string> names = image_file_names();
      std::size_t image = 0;
      for (const Section& s : sections_)
        for (const Gallery_case& c : s.cases)
          for (const auto& img : c.images)
            fair::io::write_text_file((fs::path(directory) / "figures" / names[image++]).string(), img.second);
    }
    fair::io::write_text_file((fs::path(directory) / "index.html").string(), html(inline_svg));
  }

private:
  struct Section {
    std::string title, introduction;
    std::vector<Gallery_case> cases;
  };

  static std::string slug(const std::string& text) {
    std::string out;
    for (char c : text) {
      const unsigned char u = static_cast<unsigned char>(c);
      if (std::isalnum(u)) out += static_cast<char>(std::tolower(u));
      else if (!out.empty() && out.back() != '-') out += '-';
      if (out.size() >= 40) break;
    }
    while (!out.empty() && out.back() == '-') out.pop_back();
    return out.empty() ? std::string("figure") : out;
  }

  // An SVG document without a leading XML declaration, for inlining.
  static std::string svg_body(const std::string& svg) {
    const std::size_t k = svg.find("<svg");
    return k == std::string::npos ? svg : svg.substr(k);
  }

  std::string title_, introduction_;
  std::vector<Section> sections_;
};

} // namespace fair_curves

#endif // FAIR_CURVES_GALLERY_H
