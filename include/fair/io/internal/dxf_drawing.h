// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The DXF text of fair::io::write_dxf (fair/io/write_dxf.h, whose file comment describes the
// drawing): the group-code writer, the fixed handles, the curve as checked doubles, and the
// sections of an R2000 (AC1015) drawing holding one SPLINE entity per curve.

#ifndef FAIR_IO_INTERNAL_DXF_DRAWING_H
#define FAIR_IO_INTERNAL_DXF_DRAWING_H

#include <fair/Errors.h>
#include <fair/io/internal/nearest_double.h>
#include <fair/Nurbs_curve_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace fair {
namespace io {
namespace internal {


/// The DXF group-code/value writer: a line with the code, a line with the value.
class Dxf_writer {
public:
  explicit Dxf_writer(std::ostream& out) : out_(out) {}
  void tag(int code, const std::string& value) { out_ << code << '\n' << value << '\n'; }
  void tag(int code, long value) { out_ << code << '\n' << value << '\n'; }
  void tag(int code, int value) { tag(code, static_cast<long>(value)); }
  void tag(int code, std::size_t value) { tag(code, static_cast<long>(value)); }
  void real(int code, double value) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", value == 0 ? 0.0 : value);  // no "-0"
    tag(code, std::string(buffer));
  }
  /// A point: codes c, c + 10, c + 20 (x, y, z).
  void point(int code, double x, double y, double z = 0) {
    real(code, x);
    real(code + 10, y);
    real(code + 20, z);
  }
  /// A handle (groups 5, 105, 330, 350): upper-case hexadecimal.
  void handle(int code, unsigned long h) {
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "%lX", h);
    tag(code, std::string(buffer));
  }

private:
  std::ostream& out_;
};

/// The fixed handles of the drawing's tables, blocks and objects; the SPLINEs follow from
/// first_entity on, and $HANDSEED is one past the last.
struct Dxf_handles {
  enum : unsigned long {
    root_dictionary = 0x1, group_dictionary, vport_table, vport_active, ltype_table, ltype_byblock,
    ltype_bylayer, ltype_continuous, layer_table, layer_0, style_table, style_standard, view_table,
    ucs_table, appid_table, appid_acad, dimstyle_table, dimstyle_standard, block_record_table,
    model_space_record, paper_space_record, model_space_block, model_space_end, paper_space_block,
    paper_space_end, first_entity = 0x100
  };
};

/// The nearest double of x, finite, or the error naming `what`.
template <class FT>
double finite_double(const FT& x, std::size_t curve, const char* what, std::size_t index) {
  const double d = nearest_double_of(x);
  if (!std::isfinite(d))
    throw Precondition_error("fair::io::write_dxf: curve " + std::to_string(curve) + ": " + what + " " +
                             std::to_string(index) + " is not finite as a double");
  return d;
}

/// The curve as doubles, checked before anything is written (a failure writes nothing).
struct Dxf_spline {
  std::size_t degree = 0;
  bool rational = false, closed = false;
  std::vector<double> knots, weights, x, y;
};

template <class K>
Dxf_spline dxf_spline(const Nurbs_curve_2<K>& c, std::size_t index) {
  Dxf_spline s;
  s.degree = c.degree();
  s.rational = c.is_rational();
  s.closed = c.is_closed();
  for (std::size_t i = 0; i < c.knots().size(); ++i) s.knots.push_back(finite_double(c.knots()[i], index, "knot", i));
  for (std::size_t i = 0; i < c.control_points().size(); ++i) {
    s.x.push_back(finite_double(c.control_points()[i].x(), index, "control point x", i));
    s.y.push_back(finite_double(c.control_points()[i].y(), index, "control point y", i));
    if (s.rational) s.weights.push_back(finite_double(c.weights()[i], index, "weight", i));
  }
  return s;
}

inline void dxf_table_begin(Dxf_writer& w, const char* name, unsigned long handle, std::size_t entries) {
  w.tag(0, "TABLE");
  w.tag(2, name);
  w.handle(5, handle);
  w.tag(330, "0");
  w.tag(100, "AcDbSymbolTable");
  w.tag(70, entries);
}

/// The common head of a table record: handle (group 5, DIMSTYLE 105), owner, subclass markers,
/// name, standard flags 0.
inline void dxf_record(Dxf_writer& w, const char* type, unsigned long handle, unsigned long table,
                       const char* subclass, const char* name) {
  w.tag(0, type);
  w.handle(std::string(type) == "DIMSTYLE" ? 105 : 5, handle);
  w.handle(330, table);
  w.tag(100, "AcDbSymbolTableRecord");
  w.tag(100, subclass);
  w.tag(2, name);
  w.tag(70, 0);
}

inline void dxf_tables(Dxf_writer& w) {
  typedef Dxf_handles H;
  w.tag(0, "SECTION");
  w.tag(2, "TABLES");

  dxf_table_begin(w, "VPORT", H::vport_table, 1);
  dxf_record(w, "VPORT", H::vport_active, H::vport_table, "AcDbViewportTableRecord", "*ACTIVE");
  w.point(10, 0, 0, 0); // lower left / upper right of the viewport (2D points: codes 10/20, 11/21)
  w.real(11, 1);
  w.real(21, 1);
  w.real(12, 0);  // view centre
  w.real(22, 0);
  w.real(13, 0);  // snap base
  w.real(23, 0);
  w.real(14, 1);  // snap spacing
  w.real(24, 1);
  w.real(15, 1);  // grid spacing
  w.real(25, 1);
  w.point(16, 0, 0, 1);  // view direction
  w.point(17, 0, 0, 0);  // view target
  w.real(40, 1);   // view height
  w.real(41, 1);   // aspect ratio
  w.real(42, 50);  // lens length
  w.real(43, 0);
  w.real(44, 0);
  w.real(50, 0);
  w.real(51, 0);
  w.tag(71, 0);
  w.tag(72, 100);
  w.tag(73, 1);
  w.tag(74, 3);
  w.tag(75, 0);
  w.tag(76, 0);
  w.tag(77, 0);
  w.tag(78, 0);
  w.tag(0, "ENDTAB");

  dxf_table_begin(w, "LTYPE", H::ltype_table, 3);
  const struct {
    unsigned long handle;
    const char* name;
    const char* description;
  } ltypes[] = {{H::ltype_byblock, "ByBlock", ""}, {H::ltype_bylayer, "ByLayer", ""},
                {H::ltype_continuous, "Continuous", "Solid line"}};
  for (const auto& l : ltypes) {
    dxf_record(w, "LTYPE", l.handle, H::ltype_table, "AcDbLinetypeTableRecord", l.name);
    w.tag(3, l.description);
    w.tag(72, 65);  // alignment 'A'
    w.tag(73, 0);   // no dash elements
    w.real(40, 0);  // pattern length
  }
  w.tag(0, "ENDTAB");

  dxf_table_begin(w, "LAYER", H::layer_table, 1);
  dxf_record(w, "LAYER", H::layer_0, H::layer_table, "AcDbLayerTableRecord", "0");
  w.tag(62, 7);            // colour: white/black
  w.tag(6, "Continuous");  // line type
  w.tag(370, -3);          // line weight: default
  w.tag(0, "ENDTAB");

  dxf_table_begin(w, "STYLE", H::style_table, 1);
  dxf_record(w, "STYLE", H::style_standard, H::style_table, "AcDbTextStyleTableRecord", "Standard");
  w.real(40, 0);   // no fixed height
  w.real(41, 1);   // width factor
  w.real(50, 0);   // oblique angle
  w.tag(71, 0);    // generation flags
  w.real(42, 2.5); // last height used
  w.tag(3, "txt"); // font file
  w.tag(4, "");
  w.tag(0, "ENDTAB");

  dxf_table_begin(w, "VIEW", H::view_table, 0);
  w.tag(0, "ENDTAB");
  dxf_table_begin(w, "UCS", H::ucs_table, 0);
  w.tag(0, "ENDTAB");

  dxf_table_begin(w, "APPID", H::appid_table, 1);
  dxf_record(w, "APPID", H::appid_acad, H::appid_table, "AcDbRegAppTableRecord", "ACAD");
  w.tag(0, "ENDTAB");

  // DIMSTYLE: its table has an extra subclass marker and its records the handle code 105.
  w.tag(0, "TABLE");
  w.tag(2, "DIMSTYLE");
  w.handle(5, H::dimstyle_table);
  w.tag(330, "0");
  w.tag(100, "AcDbSymbolTable");
  w.tag(70, 1);
  w.tag(100, "AcDbDimStyleTable");
  w.tag(71, 0);
  dxf_record(w, "DIMSTYLE", H::dimstyle_standard, H::dimstyle_table, "AcDbDimStyleTableRecord", "Standard");
  w.tag(0, "ENDTAB");

  dxf_table_begin(w, "BLOCK_RECORD", H::block_record_table, 2);
  dxf_record(w, "BLOCK_RECORD", H::model_space_record, H::block_record_table, "AcDbBlockTableRecord", "*Model_Space");
  dxf_record(w, "BLOCK_RECORD", H::paper_space_record, H::block_record_table, "AcDbBlockTableRecord", "*Paper_Space");
  w.tag(0, "ENDTAB");
  w.tag(0, "ENDSEC");
}

inline void dxf_block(Dxf_writer& w, unsigned long begin, unsigned long end, unsigned long record, const char* name,
                      bool paper_space) {
  w.tag(0, "BLOCK");
  w.handle(5, begin);
  w.handle(330, record);
  w.tag(100, "AcDbEntity");
  if (paper_space) w.tag(67, 1);
  w.tag(8, "0");
  w.tag(100, "AcDbBlockBegin");
  w.tag(2, name);
  w.tag(70, 0);
  w.point(10, 0, 0, 0);
  w.tag(3, name);
  w.tag(1, "");
  w.tag(0, "ENDBLK");
  w.handle(5, end);
  w.handle(330, record);
  w.tag(100, "AcDbEntity");
  if (paper_space) w.tag(67, 1);
  w.tag(8, "0");
  w.tag(100, "AcDbBlockEnd");
}

inline void dxf_spline_entity(Dxf_writer& w, const Dxf_spline& s, unsigned long handle) {
  w.tag(0, "SPLINE");
  w.handle(5, handle);
  w.handle(330, Dxf_handles::model_space_record);
  w.tag(100, "AcDbEntity");
  w.tag(8, "0");
  w.tag(100, "AcDbSpline");
  w.point(210, 0, 0, 1);
  w.tag(70, 8 + (s.rational ? 4 : 0) + (s.closed ? 1 + 2 : 0));
  w.tag(71, s.degree);
  w.tag(72, s.knots.size());
  w.tag(73, s.x.size());
  w.tag(74, 0);
  w.real(42, 1e-10);  // knot tolerance
  w.real(43, 1e-10);  // control point tolerance
  for (double u : s.knots) w.real(40, u);
  for (double v : s.weights) w.real(41, v);
  for (std::size_t i = 0; i < s.x.size(); ++i) w.point(10, s.x[i], s.y[i], 0);
}

/// The whole drawing (fair/io/write_dxf.h, file comment): HEADER with the extent of the control
/// points, the empty CLASSES, the TABLES, the two BLOCKS, one SPLINE per curve, the OBJECTS.
inline void dxf_drawing(std::ostream& out, const std::vector<Dxf_spline>& splines) {
  typedef Dxf_handles H;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  // The control polygon's box contains the curve (convex hull property, weights > 0).
  for (const Dxf_spline& s : splines)
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      lo[0] = std::min(lo[0], s.x[k]);
      hi[0] = std::max(hi[0], s.x[k]);
      lo[1] = std::min(lo[1], s.y[k]);
      hi[1] = std::max(hi[1], s.y[k]);
    }
  if (splines.empty()) lo[0] = lo[1] = hi[0] = hi[1] = 0;

  std::ostringstream text;
  Dxf_writer w(text);
  w.tag(0, "SECTION");
  w.tag(2, "HEADER");
  w.tag(9, "$ACADVER");
  w.tag(1, "AC1015");
  w.tag(9, "$HANDSEED");
  w.handle(5, H::first_entity + splines.size());
  w.tag(9, "$EXTMIN");
  w.point(10, lo[0], lo[1], 0);
  w.tag(9, "$EXTMAX");
  w.point(10, hi[0], hi[1], 0);
  w.tag(0, "ENDSEC");

  w.tag(0, "SECTION");
  w.tag(2, "CLASSES");
  w.tag(0, "ENDSEC");

  dxf_tables(w);

  w.tag(0, "SECTION");
  w.tag(2, "BLOCKS");
  dxf_block(w, H::model_space_block, H::model_space_end, H::model_space_record, "*Model_Space", false);
  dxf_block(w, H::paper_space_block, H::paper_space_end, H::paper_space_record, "*Paper_Space", true);
  w.tag(0, "ENDSEC");

  w.tag(0, "SECTION");
  w.tag(2, "ENTITIES");
  for (std::size_t i = 0; i < splines.size(); ++i) dxf_spline_entity(w, splines[i], H::first_entity + i);
  w.tag(0, "ENDSEC");

  w.tag(0, "SECTION");
  w.tag(2, "OBJECTS");
  w.tag(0, "DICTIONARY");
  w.handle(5, H::root_dictionary);
  w.tag(330, "0");
  w.tag(100, "AcDbDictionary");
  w.tag(281, 1);
  w.tag(3, "ACAD_GROUP");
  w.handle(350, H::group_dictionary);
  w.tag(0, "DICTIONARY");
  w.handle(5, H::group_dictionary);
  w.handle(330, H::root_dictionary);
  w.tag(100, "AcDbDictionary");
  w.tag(281, 1);
  w.tag(0, "ENDSEC");
  w.tag(0, "EOF");
  out << text.str();
}

} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_DXF_DRAWING_H
