// DXF writer (write_dxf.h). Group codes and the R2000 object structure follow Autodesk's DXF
// Reference (the R12 and AutoCAD 2000 editions): symbol tables own their records by handle (330),
// entities are owned by the *Model_Space block record, and the root dictionary opens OBJECTS.
// Sections: 1. versions and layers  2. numbers and groups  3. entities  4. the file
#include "kerf/converter/formats/dxf/write_dxf.h"

#include "kerf/geometry/vec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace kerf::converter {

// ---- 1. versions and layers ---------------------------------------------------------------------

std::optional<DxfVersion> dxfVersionNamed(std::string_view name) {
  std::string n(name);
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (n == "r12" || n == "ac1009") return DxfVersion::R12;
  if (n == "r2000" || n == "ac1015") return DxfVersion::R2000;
  return std::nullopt;
}

namespace {

struct Layer {
  std::string name;
  int colour;  // AutoCAD colour index
};
/// The fixed layers, then (a program cut in several passes) LOWER_PASS1, UPPER_PASS1, LOWER_PASS2, ...
const Layer kLayers[] = {{"0", 7}, {"LOWER", 5}, {"UPPER", 3}, {"PROGRAMMED", 8}, {"RAPID", 2}};
enum LayerIndex { kLower = 1, kUpper = 2, kProgrammed = 3, kRapid = 4, kFirstPass = 5 };

/// The layers of a drawing whose moves are in at most `passes` passes (0 or 1: the fixed ones),
/// and DEVIATION last when there are elements out of tolerance.
/// Pass colours: red, blue, green, yellow, magenta, cyan (AutoCAD indices 1 5 3 2 6 4), repeating.
std::vector<Layer> layersFor(std::size_t passes, bool deviation) {
  std::vector<Layer> out(std::begin(kLayers), std::end(kLayers));
  constexpr int kPassColours[] = {1, 5, 3, 2, 6, 4};
  if (passes >= 2)
    for (std::size_t k = 1; k <= passes; ++k)
      for (const char* plane : {"LOWER", "UPPER"})
        out.push_back(
            {std::string(plane) + "_PASS" + std::to_string(k), kPassColours[(k - 1) % std::size(kPassColours)]});
  if (deviation) out.push_back({"DEVIATION", 6});  // magenta, last (deviationLayer)
  return out;
}
/// The DEVIATION layer's index: after the fixed layers and the pass layers (layersFor).
int deviationLayer(std::size_t passes) { return kFirstPass + (passes >= 2 ? 2 * static_cast<int>(passes) : 0); }
/// The layer of a cut move of pass `pass` (1-based) on the lower or the upper plane.
int passLayer(std::size_t pass, bool upper) { return kFirstPass + 2 * static_cast<int>(pass - 1) + (upper ? 1 : 0); }

struct Item {
  geometry::Segment segment;
  double z = 0.0;
  int layer = kLower;
};

// ---- 2. numbers and groups ----------------------------------------------------------------------

/// A real number as DXF text: fixed notation (no exponent, which some readers refuse), trailing
/// zeros trimmed, at least one decimal, no "-0".
std::string number(double v) {
  if (std::abs(v) < 5e-11) v = 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10f", v);
  std::string s(buf);
  while (s.size() > 2 && s.back() == '0' && s[s.size() - 2] != '.') s.pop_back();
  if (s == "-0.0") s = "0.0";
  return s;
}

double degrees(double radians) {
  double d = radians * 180.0 / std::numbers::pi;
  d = std::fmod(d, 360.0);
  if (d < 0) d += 360.0;
  if (d >= 360.0 - 1e-12) d = 0.0;
  return d;
}

class Out {
 public:
  explicit Out(bool handles) : handles_(handles) {}

  void g(int code, std::string_view value) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%3d", code);
    text_ += buf;
    text_ += "\r\n";
    text_ += value;
    text_ += "\r\n";
  }
  void g(int code, double value) { g(code, number(value)); }
  void gi(int code, long value) { g(code, std::to_string(value)); }
  void point(int code, const geometry::Vec2& p, double z) {
    g(code, p.x());
    g(code + 10, p.y());
    g(code + 20, z);
  }
  /// A new handle (hex), or nothing in R12.
  std::string handle() {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%llX", static_cast<unsigned long long>(next_++));
    return buf;
  }
  [[nodiscard]] unsigned long long seed() const { return next_; }
  /// The entity's handle and owner (R2000 only).
  /// Returns the handle ("" in R12).
  std::string owned(const std::string& owner, int handleCode = 5) {
    if (!handles_) return {};
    std::string h = handle();
    g(handleCode, h);
    g(330, owner);
    return h;
  }
  [[nodiscard]] bool handles() const { return handles_; }
  std::string text_;

 private:
  bool handles_;
  unsigned long long next_ = 0x20;  // below: the fixed handles of the structure (see writeDxf)
};

void section(Out& o, const char* name) {
  o.g(0, "SECTION");
  o.g(2, name);
}
void endsec(Out& o) { o.g(0, "ENDSEC"); }

/// Opens a symbol table; returns its handle (R2000).
std::string table(Out& o, const char* name, long count, const char* subclass = nullptr) {
  o.g(0, "TABLE");
  o.g(2, name);
  std::string h;
  if (o.handles()) {
    h = o.handle();
    o.g(5, h);
    o.g(330, "0");
    o.g(100, "AcDbSymbolTable");
  }
  o.gi(70, count);
  if (subclass && o.handles()) {
    o.g(100, subclass);
    o.gi(71, 0);
  }
  return h;
}

/// Writes a symbol table record's head; returns its handle (R2000).
std::string record(Out& o, const char* type, const std::string& tableHandle, const char* subclass, const char* name,
                   int handleCode = 5) {
  o.g(0, type);
  std::string h;
  if (o.handles()) {
    h = o.owned(tableHandle, handleCode);
    o.g(100, "AcDbSymbolTableRecord");
    o.g(100, subclass);
  }
  o.g(2, name);
  o.gi(70, 0);
  return h;
}

void entityHead(Out& o, const char* type, const std::string& owner, const std::string& layer, const char* subclass) {
  o.g(0, type);
  o.owned(owner);
  if (o.handles()) o.g(100, "AcDbEntity");
  o.g(8, layer);
  if (o.handles()) o.g(100, subclass);
}

// ---- 3. entities --------------------------------------------------------------------------------

void writeItem(Out& o, const Item& it, const std::vector<Layer>& layers, const std::string& owner,
               DxfWriteCounts& counts) {
  const geometry::Segment& s = it.segment;
  const std::string& layer = layers[static_cast<std::size_t>(it.layer)].name;
  if (!s.isArc()) {
    entityHead(o, "LINE", owner, layer, "AcDbLine");
    o.point(10, s.start, it.z);
    o.point(11, s.end, it.z);
    ++counts.lines;
    return;
  }
  const bool full = std::abs(std::abs(s.sweep) - 2 * std::numbers::pi) < 1e-12;
  entityHead(o, full ? "CIRCLE" : "ARC", owner, layer, "AcDbCircle");
  o.point(10, s.centre, it.z);
  o.g(40, s.radius());
  if (full) {
    ++counts.circles;
    return;
  }
  // DXF arcs run counter-clockwise from group 50 to group 51.
  const double a = s.startAngle(), b = s.startAngle() + s.sweep;
  if (o.handles()) o.g(100, "AcDbArc");
  o.g(50, degrees(s.sweep > 0 ? a : b));
  o.g(51, degrees(s.sweep > 0 ? b : a));
  ++counts.arcs;
}

/// The most passes any contour has (DxfWriteOptions::movePass).
std::size_t passCount(const DxfWriteOptions& options) {
  std::size_t most = 0;
  for (const std::uint8_t p : options.movePass) most = std::max<std::size_t>(most, p);
  return most;
}

std::vector<Item> itemsOf(const Toolpath& tp, const DxfWriteOptions& options) {
  std::vector<Item> items;
  const std::size_t passes = passCount(options);
  const bool heights = tp.isTaper() && tp.heights.known;
  const double zLower = heights ? tp.heights.planes.lower : 0.0;
  const double zUpper = heights ? tp.heights.planes.upper : 0.0;
  auto usable = [](const geometry::Segment& s) { return s.length() > 1e-12; };
  for (std::size_t i = 0; i < tp.moves.size(); ++i) {
    const Move& m = tp.moves[i];
    if (!m.isCut()) {
      if (options.rapids && usable(m.lower)) items.push_back({m.lower, zLower, kRapid});
      continue;
    }
    const std::size_t pass = i < options.movePass.size() ? options.movePass[i] : 0;
    const bool byPass = pass > 0 && passes > 1;
    if (usable(m.lower)) items.push_back({m.lower, zLower, byPass ? passLayer(pass, false) : kLower});
    if (tp.isTaper() && usable(tp.upper[i]))
      items.push_back({tp.upper[i], zUpper, byPass ? passLayer(pass, true) : kUpper});
  }
  if (options.programmed && !tp.programmed.empty()) {
    for (std::size_t i = 0; i < tp.programmed.size() && i < tp.offsetRole.size(); ++i) {
      if (tp.offsetRole[i] == OffsetRole::Corner) continue;  // no programmed move of its own
      if (!tp.moves[i].isCut() || !usable(tp.programmed[i])) continue;
      // One programmed move can be split over several applied pieces: write it once.
      if (!items.empty() && items.back().layer == kProgrammed && i > 0 &&
          tp.programmed[i - 1].start == tp.programmed[i].start && tp.programmed[i - 1].end == tp.programmed[i].end)
        continue;
      items.push_back({tp.programmed[i], zLower, kProgrammed});
    }
  }
  for (const geometry::Segment& s : options.deviation)
    if (usable(s)) items.push_back({s, zLower, deviationLayer(passes)});
  return items;
}

void extents(Out& o, const std::vector<Item>& items) {
  geometry::Vec2 lo(0, 0), hi(0, 0);
  double zlo = 0, zhi = 0;
  bool any = false;
  for (const Item& it : items) {
    const geometry::Box b = it.segment.bounds();
    if (!any) {
      lo = b.min;
      hi = b.max;
      zlo = zhi = it.z;
      any = true;
    } else {
      lo = lo.cwiseMin(b.min);
      hi = hi.cwiseMax(b.max);
      zlo = std::min(zlo, it.z);
      zhi = std::max(zhi, it.z);
    }
  }
  o.g(9, "$EXTMIN");
  o.point(10, lo, zlo);
  o.g(9, "$EXTMAX");
  o.point(10, hi, zhi);
}

/// The model and paper space block records' handles (R2000; empty in R12).
struct BlockRecords {
  std::string model, paper;
};

// ---- 4. the file --------------------------------------------------------------------------------

/// The TABLES section: viewport, line types, the layers, and (R2000) the tables AutoCAD requires.
BlockRecords writeTables(Out& body, const std::vector<Layer>& layerList, bool r2000) {
  BlockRecords out;
  section(body, "TABLES");
  if (r2000) {
    const std::string vport = table(body, "VPORT", 1);
    record(body, "VPORT", vport, "AcDbViewportTableRecord", "*Active");
    body.point(10, {0, 0}, 0);  // lower left, upper right of the viewport (display fractions)
    body.g(11, 1.0);
    body.g(21, 1.0);
    body.g(40, 100.0);  // view height
    body.g(41, 1.5);    // aspect
    body.g(0, "ENDTAB");
  }
  const std::string ltypes = table(body, "LTYPE", r2000 ? 3 : 1);
  for (const char* name : {"ByBlock", "ByLayer", "Continuous"}) {
    if (!r2000 && std::string_view(name) != "Continuous") continue;
    record(body, "LTYPE", ltypes, "AcDbLinetypeTableRecord", r2000 ? name : "CONTINUOUS");
    body.g(3, std::string_view(name) == "Continuous" ? "Solid line" : "");
    body.gi(72, 65);
    body.gi(73, 0);
    body.g(40, 0.0);
  }
  body.g(0, "ENDTAB");
  const std::string layers = table(body, "LAYER", static_cast<long>(layerList.size()));
  for (const Layer& l : layerList) {
    record(body, "LAYER", layers, "AcDbLayerTableRecord", l.name.c_str());
    body.gi(62, l.colour);
    body.g(6, r2000 ? "Continuous" : "CONTINUOUS");
    if (r2000) body.gi(370, -3);  // lineweight: default
  }
  body.g(0, "ENDTAB");
  if (r2000) {
    const std::string styles = table(body, "STYLE", 1);
    record(body, "STYLE", styles, "AcDbTextStyleTableRecord", "Standard");
    body.g(40, 0.0);
    body.g(41, 1.0);
    body.g(50, 0.0);
    body.gi(71, 0);
    body.g(42, 2.5);
    body.g(3, "txt");
    body.g(4, "");
    body.g(0, "ENDTAB");
    table(body, "VIEW", 0);
    body.g(0, "ENDTAB");
    table(body, "UCS", 0);
    body.g(0, "ENDTAB");
    const std::string apps = table(body, "APPID", 1);
    record(body, "APPID", apps, "AcDbRegAppTableRecord", "ACAD");
    body.g(0, "ENDTAB");
    const std::string dims = table(body, "DIMSTYLE", 1, "AcDbDimStyleTable");
    record(body, "DIMSTYLE", dims, "AcDbDimStyleTableRecord", "Standard", 105);
    body.g(0, "ENDTAB");
    const std::string blocks = table(body, "BLOCK_RECORD", 2);
    out.model = record(body, "BLOCK_RECORD", blocks, "AcDbBlockTableRecord", "*Model_Space");
    out.paper = record(body, "BLOCK_RECORD", blocks, "AcDbBlockTableRecord", "*Paper_Space");
    body.g(0, "ENDTAB");
  }
  endsec(body);

  return out;
}

/// The BLOCKS section: R2000's model and paper space blocks (empty in R12).
void writeBlocks(Out& body, const BlockRecords& records, bool r2000) {
  const std::string& modelRecord = records.model;
  const std::string& paperRecord = records.paper;
  section(body, "BLOCKS");
  if (r2000) {
    for (const auto& [name, owner] : {std::pair{"*Model_Space", modelRecord}, std::pair{"*Paper_Space", paperRecord}}) {
      // BLOCK and ENDBLK share their head: handle, owner, entity, paper space flag, layer 0.
      auto head = [&, name = name, owner = owner](const char* type, const char* subclass) {
        body.g(0, type);
        body.owned(owner);
        body.g(100, "AcDbEntity");
        if (std::string_view(name) == "*Paper_Space") body.gi(67, 1);
        body.g(8, "0");
        body.g(100, subclass);
      };
      head("BLOCK", "AcDbBlockBegin");
      body.g(2, name);
      body.gi(70, 0);
      body.point(10, {0, 0}, 0);
      body.g(3, name);
      body.g(1, "");
      head("ENDBLK", "AcDbBlockEnd");
    }
  }
  endsec(body);
}

/// R2000's OBJECTS section: the root dictionary and its ACAD_GROUP dictionary.
void writeObjects(Out& body, const std::string& root, const std::string& groups) {
  section(body, "OBJECTS");
  body.g(0, "DICTIONARY");
  body.g(5, root);
  body.g(330, "0");
  body.g(100, "AcDbDictionary");
  body.gi(281, 1);
  body.g(3, "ACAD_GROUP");
  body.g(350, groups);
  body.g(0, "DICTIONARY");
  body.g(5, groups);
  body.g(330, root);
  body.g(100, "AcDbDictionary");
  body.gi(281, 1);
  endsec(body);
}

/// The HEADER (and R2000's empty CLASSES): version, extents, units, and the next free handle.
Out writeHeader(const std::vector<Item>& items, bool r2000, unsigned long long handleSeed) {
  Out head(false);
  head.g(999, "Kerf: the wire path of a checked program");
  section(head, "HEADER");
  head.g(9, "$ACADVER");
  head.g(1, r2000 ? "AC1015" : "AC1009");
  head.g(9, "$INSBASE");
  head.point(10, {0, 0}, 0);
  extents(head, items);
  if (r2000) {
    head.g(9, "$INSUNITS");
    head.gi(70, 4);  // millimetres
    head.g(9, "$MEASUREMENT");
    head.gi(70, 1);  // metric
    head.g(9, "$HANDSEED");
    char buf[24];
    std::snprintf(buf, sizeof buf, "%llX", handleSeed);
    head.g(5, buf);
  }
  endsec(head);
  if (r2000) {
    section(head, "CLASSES");
    endsec(head);
  }
  return head;
}

}  // namespace

std::string writeDxf(const Toolpath& tp, const DxfWriteOptions& options, DxfWriteCounts* countsOut) {
  const std::vector<Item> items = itemsOf(tp, options);
  const std::vector<Layer> layerList = layersFor(passCount(options), !options.deviation.empty());
  DxfWriteCounts counts;
  const bool r2000 = options.version == DxfVersion::R2000;
  // The body first (it allocates the handles), then the header that names the next free one.
  Out body(r2000);
  const BlockRecords records = writeTables(body, layerList, r2000);
  writeBlocks(body, records, r2000);
  section(body, "ENTITIES");
  for (const Item& it : items) writeItem(body, it, layerList, records.model, counts);
  endsec(body);
  if (r2000) writeObjects(body, "C", "D");  // fixed handles: the root dictionary, ACAD_GROUP
  body.g(0, "EOF");
  const Out head = writeHeader(items, r2000, body.seed());
  if (countsOut) *countsOut = counts;
  return head.text_ + body.text_;
}

std::optional<EmitOutput> writeDxfProgram(const Toolpath& toolpath, const SourceFile* source,
                                          const DxfWriteOptions& options, Diagnostics& diags) {
  DxfWriteCounts counts;
  EmitOutput out;
  out.text = writeDxf(toolpath, options, &counts);
  if (counts.lines + counts.arcs + counts.circles == 0) {
    diags.error(Code::NothingToWrite, source, SourceSpan::wholeFile(),
                "nothing to write: nothing is cut, so there is no contour to draw");
    return std::nullopt;
  }
  out.what = std::to_string(counts.lines) + " lines, " + std::to_string(counts.arcs) + " arcs, " +
             std::to_string(counts.circles) + " circles";
  out.detail = std::string(" (DXF ") + (options.version == DxfVersion::R12 ? "R12" : "R2000") + ")";
  return out;
}

}  // namespace kerf::converter
