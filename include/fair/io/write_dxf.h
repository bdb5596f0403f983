// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::io::write_dxf: curves as a minimal valid AutoCAD R2000 (AC1015) DXF drawing, one SPLINE
// entity per fair::Nurbs_curve_2 (doc/io.md, "DXF"). Written here, without a DXF library
// (Debian's dxflib drops spline weights), and read back in the tests by an independent reader,
// ezdxf (test/io_export/check_dxf.py): the file opens, its audit reports no error, and ezdxf's own
// evaluation of each SPLINE traces the library's curve to 1e-12 of the extent.
//
// The drawing holds what R13 and later require (ezdxf, "DXF File Structure / Minimal DXF
// Content"; Autodesk DXF Reference 2000): HEADER with $ACADVER and $HANDSEED (and $EXTMIN,
// $EXTMAX for "zoom extents"); an empty CLASSES section; the tables VPORT (*ACTIVE), LTYPE
// (ByBlock, ByLayer, Continuous), LAYER (0), STYLE (Standard), VIEW, UCS, APPID (ACAD), DIMSTYLE
// (Standard), BLOCK_RECORD (*Model_Space, *Paper_Space); the two BLOCKS; the ENTITIES; OBJECTS
// with the root dictionary and its ACAD_GROUP dictionary. Every object has a unique handle and
// its owner (group 330), as AutoCAD checks.
//
// The SPLINE entity (AcDbSpline): normal (0,0,1); flags 70 = 8 (planar) + 4 (rational, when the
// weights differ) + 1 + 2 (closed and periodic, for a closed curve); 71 degree; 72/73/74 the
// numbers of knots, control points and fit points (0); the full knot vector (40), the weights
// (41) when rational, the control points (10/20/30). A closed curve is written in the periodic
// unclamped form of Nurbs_curve_2 (the last p control points repeat the first p, n + p + 1
// knots): the form ezdxf writes for a closed spline (Spline.set_closed: flags CLOSED|PERIODIC,
// control points extended by the first p) and BricsCAD reads; the Autodesk reference's
// alternative of n + 1 knots for a periodic spline is not read by BricsCAD (ezdxf's note).
// Every reader evaluating the knots and control points as given (ezdxf's BSpline, OpenCASCADE)
// then gets the same curve. The parameter is the library's; ezdxf normalises a knot vector
// that does not start at 0 to [0, 1], which maps u to (u - u_0) / (u_last - u_0).
//
// Numbers: 17 significant digits (%.17g), which round-trip every double; in an exact kernel the
// nearest double of each coordinate, knot and weight (DXF has no exact numbers).
//
// Errors: fair::Precondition_error for a coordinate, knot or weight whose double is not finite
// (a huge exact value), naming the curve and the index; every value is checked before anything
// is written, so a failure leaves `out` untouched.
//
// The text itself is made in fair/io/internal/dxf_drawing.h.

#ifndef FAIR_IO_WRITE_DXF_H
#define FAIR_IO_WRITE_DXF_H

#include <fair/Nurbs_curve_2.h>
#include <fair/io/internal/dxf_drawing.h>

#include <cstddef>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// The curves as an R2000 DXF drawing (file comment), one SPLINE per curve in order.
/// \throws Precondition_error for a value that is not finite as a double (nothing written).
template <class K>
void write_dxf(std::ostream& out, const std::vector<Nurbs_curve_2<K>>& curves) {
  std::vector<internal::Dxf_spline> splines;  // every value checked before anything is written
  for (std::size_t i = 0; i < curves.size(); ++i) splines.push_back(internal::dxf_spline(curves[i], i));
  internal::dxf_drawing(out, splines);
}

template <class K>
void write_dxf(std::ostream& out, const Nurbs_curve_2<K>& curve) {
  write_dxf(out, std::vector<Nurbs_curve_2<K>>{curve});
}

/// The drawing as text.
template <class K>
std::string dxf_text(const std::vector<Nurbs_curve_2<K>>& curves) {
  std::ostringstream out;
  write_dxf(out, curves);
  return out.str();
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_WRITE_DXF_H
