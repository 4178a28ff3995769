// Curves as drawings (read_curve.h). Expressions are parsed and evaluated by muparser (Debian's
// libmuparser-dev, https://beltoforion.de/en/muparser/): bytecode, so the thousands of evaluations
// a biarc fit makes cost little. The library is loaded when a curve is first read, through its C
// interface (muParserDLL.h): linked, it and the OpenMP runtime it needs would be loaded by every run
// of kerf.
// Sections: 1. expressions (muparser)  2. the drawing and its fit  3. point lists  4. parametric curves
//           5. reading a curve
#include "kerf/converter/formats/curve/read_curve.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/biarc.h"

#include <muParserDLL.h>

#include <dlfcn.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kerf::converter {

namespace {

/// One statement of the text: where it starts, its words.
struct Statement {
  std::uint32_t offset = 0;  ///< of its first non-blank character
  std::string_view text;     ///< trimmed, comment removed
};

// ---- 1. expressions (muparser) ------------------------------------------------------------------

/// The statements of the text, or with `first`, at most the first one (what detection reads: a
/// program of megabytes is not split whole to look at its head).
std::vector<Statement> statements(std::string_view all, bool first = false) {
  std::vector<Statement> out;
  std::size_t i = 0;
  while (i <= all.size() && !(first && !out.empty())) {
    std::size_t end = i;
    while (end < all.size() && all[end] != '\n' && all[end] != ';' && all[end] != '#') ++end;
    std::size_t next = end;
    if (next < all.size() && all[next] == '#')
      while (next < all.size() && all[next] != '\n') ++next;
    std::size_t a = i, b = end;
    while (a < b && std::isspace(static_cast<unsigned char>(all[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(all[b - 1]))) --b;
    if (b > a) out.push_back({static_cast<std::uint32_t>(a), all.substr(a, b - a)});
    i = next + 1;
  }
  return out;
}

/// The name before '=' (x, y or t), lower case; empty when the statement has no '='.
std::string nameOf(std::string_view s, std::size_t& equals) {
  equals = s.find('=');
  if (equals == std::string_view::npos) return {};
  std::string name;
  for (char c : s.substr(0, equals))
    if (!std::isspace(static_cast<unsigned char>(c)))
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

/// muparser's C interface, loaded once (KERF_MUPARSER_SONAME, from its CMake package).
struct MuParser {
  decltype(&mupCreate) create = nullptr;
  decltype(&mupRelease) release = nullptr;
  decltype(&mupDefineVar) defineVar = nullptr;
  decltype(&mupDefineConst) defineConst = nullptr;
  decltype(&mupSetExpr) setExpr = nullptr;
  decltype(&mupEval) evaluate = nullptr;
  decltype(&mupError) error = nullptr;  // true once after a call failed (and clears it)
  decltype(&mupGetErrorMsg) message = nullptr;
  decltype(&mupGetErrorPos) position = nullptr;
  std::string why;  ///< when it could not be loaded
};

template <typename F>
bool symbol(void* library, const char* name, F& f) {
  const void* address = ::dlsym(library, name);
  static_assert(sizeof f == sizeof address);
  std::memcpy(&f, &address, sizeof f);  // POSIX: dlsym's object pointer is the function's address
  return f != nullptr;
}

MuParser loadMuParser() {
  MuParser mu;
  void* library = ::dlopen(KERF_MUPARSER_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* why = ::dlerror();
    mu.why = std::string("cannot load muparser (" KERF_MUPARSER_SONAME "): ") + (why ? why : "unknown reason");
    return mu;
  }
  if (!symbol(library, "mupCreate", mu.create) || !symbol(library, "mupRelease", mu.release) ||
      !symbol(library, "mupDefineVar", mu.defineVar) || !symbol(library, "mupDefineConst", mu.defineConst) ||
      !symbol(library, "mupSetExpr", mu.setExpr) || !symbol(library, "mupEval", mu.evaluate) ||
      !symbol(library, "mupError", mu.error) || !symbol(library, "mupGetErrorMsg", mu.message) ||
      !symbol(library, "mupGetErrorPos", mu.position)) {
    mu = MuParser{};
    mu.why = "the muparser library " KERF_MUPARSER_SONAME " lacks its C interface";
  }
  return mu;  // kept loaded until the program ends
}

const MuParser& muParser() {
  static const MuParser mu = loadMuParser();
  return mu;
}

/// The longest expression muparser is given (its error messages must fit its buffer).
constexpr std::size_t kLongestExpression = 1000;

/// An expression of t, compiled once.
struct Expression {
  Expression() = default;
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;
  ~Expression() {
    if (handle) muParser().release(handle);
  }
  muParserHandle_t handle = nullptr;
  std::uint32_t offset = 0;  ///< in the source
  std::uint32_t length = 0;
};

struct CurveState {
  double t = 0.0;
  Expression x, y;
};

/// Sets up the parser; false with a diagnostic when the expression does not parse or evaluate (or
/// muparser cannot be loaded).
bool compile(Expression& e, std::string_view text, std::uint32_t offset, double* t, const SourceFile& src,
             Diagnostics& diags, const char* what) {
  e.offset = offset;
  e.length = static_cast<std::uint32_t>(text.size());
  const MuParser& mu = muParser();
  if (!mu.create) {
    diags.error(Code::CurveSyntax, &src, {offset, e.length}, std::string(what) + ": " + mu.why,
                "the curve reader needs Debian's libmuparser2v5");
    return false;
  }
  // muparser's C interface copies an error's message, which quotes the token, into one static
  // buffer of 2,048 characters: a longer expression is refused here, and the copy is made under a
  // lock (files are checked on several threads).
  if (text.size() > kLongestExpression) {
    diags.error(
        Code::CurveSyntax, &src, {offset, e.length},
        std::string(what) + ": an expression of more than " + std::to_string(kLongestExpression) + " characters");
    return false;
  }
  // muparser reads an expression up to a NUL byte: the rest would be dropped without a word.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    diags.error(Code::CurveSyntax, &src, {offset + static_cast<std::uint32_t>(nul), 1},
                std::string(what) + ": a NUL byte in the expression");
    return false;
  }
  if (!e.handle) e.handle = mu.create(muBASETYPE_FLOAT);
  if (!e.handle) {
    diags.error(Code::CurveSyntax, &src, {offset, e.length}, std::string(what) + ": muparser could not start");
    return false;
  }
  if (t) mu.defineVar(e.handle, "t", t);
  mu.defineConst(e.handle, "pi", std::numbers::pi);
  const std::string expression(text);
  mu.setExpr(e.handle, expression.c_str());
  bool failed = mu.error(e.handle);
  if (!failed) {
    (void)mu.evaluate(e.handle);  // muparser finds most errors when it first evaluates
    failed = mu.error(e.handle);
  }
  if (failed) {
    const auto pos = mu.position(e.handle);
    std::string message;
    {
      static std::mutex lock;
      const std::lock_guard<std::mutex> hold(lock);
      const char* m = mu.message(e.handle);
      message = m ? m : "not an expression";
    }
    const std::uint32_t at = pos >= 0 && static_cast<std::size_t>(pos) < text.size()
                                 ? offset + static_cast<std::uint32_t>(pos)
                                 : offset + static_cast<std::uint32_t>(text.size() ? text.size() - 1 : 0);
    diags.error(Code::CurveSyntax, &src, {at, 1}, std::string(what) + ": " + message,
                "muparser's syntax: + - * / ^, sin cos tan asin acos atan exp ln log10 sqrt abs ..., pi; "
                "the parameter is t");
    return false;
  }
  return true;
}

double eval(Expression& e) {
  const MuParser& mu = muParser();
  const double v = mu.evaluate(e.handle);
  return mu.error(e.handle) ? std::nan("") : v;
}

// ---- 2. the drawing and its fit -----------------------------------------------------------------

void fillDrawing(Drawing& d, const geometry::BiarcFit& fit, const char* entity, SourceSpan span, std::uint32_t line) {
  d.entities[entity] = 1;
  for (const geometry::Segment& s : fit.segments) {
    DrawingElement e;
    e.segment = s;
    e.entity = entity;
    e.where = line;
    e.span = span;
    d.elements.push_back(e);
  }
  d.ok = true;
}

/// The fit's verdict: a note with the spans, or an error.
bool reportFit(const geometry::BiarcFit& fit, const CurveOptions& o, const SourceFile& src, SourceSpan span,
               Diagnostics& diags) {
  if (fit.overBudget) {
    diags.error(Code::CurveFit, &src, span,
                "the curve needs more than " + std::to_string(o.maxSpans) + " biarc spans within " +
                    formatFixed(o.tolerance * 1000, 1) + " um",
                "a larger --curve-tolerance, or a shorter range");
    return false;
  }
  if (fit.swings) {
    diags.error(Code::CurveFit, &src, span,
                "the curve through these points swings out far beyond them (more than ten times their extent): "
                "the points are very unevenly spaced",
                "give the points more evenly, or split the list where they jump");
    return false;
  }
  if (!fit.ok) {
    double where = fit.spans.empty() ? 0.0 : fit.spans.back().t1;
    diags.error(Code::CurveFit, &src, span,
                "the curve cannot be fitted with tangent-continuous arcs within " + formatFixed(o.tolerance * 1000, 1) +
                    " um near t = " + formatFixed(where, 6) + ": it has a cusp or a corner there",
                "split the range at the corner");
    return false;
  }
  std::string list;
  for (std::size_t k = 0; k < fit.spans.size() && k < 40; ++k)
    list += (k ? ", " : "") + formatFixed(fit.spans[k].error * 1000, 1);
  if (fit.spans.size() > 40) list += ", ...";
  diags.note(Code::CurveFit, &src, span,
             "fitted with " + std::to_string(fit.spans.size()) + " biarc span" + (fit.spans.size() == 1 ? "" : "s") +
                 " (" + std::to_string(fit.segments.size()) + " arcs), largest error " +
                 formatFixed(fit.maxError * 1000, 2) + " um within " + formatFixed(o.tolerance * 1000, 1) +
                 " um; span errors in um: " + list);
  return true;
}

}  // namespace

// ---- 3. point lists -----------------------------------------------------------------------------

bool looksLikeCurve(std::string_view text) {
  for (const Statement& s : statements(text, true)) {
    std::size_t eq = 0;
    const std::string name = nameOf(s.text, eq);
    if (name == "x" || name == "y" || name == "t") return true;
    std::string word;
    for (char c : s.text) word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return word == "points";
  }
  return false;
}

namespace {

/// A statement's place in the file.
SourceSpan spanOf(const Statement& s) { return SourceSpan{s.offset, static_cast<std::uint32_t>(s.text.size())}; }

/// Points of a point list lie within this many mm of the origin (as drawings do, K0132).
constexpr double kLargestCurveCoordinate = 1e6;

/// A point list (`points`, then X Y per line) into d: the points range-checked and counted at
/// their lines, then fitted (K0130, K0131).
void readPointList(const SourceFile& src, const std::vector<Statement>& st, const CurveOptions& o,
                   const geometry::BiarcOptions& bo, Diagnostics& diags, Drawing& d) {
  std::vector<geometry::Vec2> pts;
  bool ok = true;
  for (std::size_t k = 1; k < st.size(); ++k) {
    std::string_view s = st[k].text;
    std::size_t cut = s.find(',');
    if (cut == std::string_view::npos) cut = s.find_first_of(" \t");
    double x = 0, y = 0;
    if (cut == std::string_view::npos || !parseNumberField(s.substr(0, cut), x) ||
        !parseNumberField(s.substr(cut + 1), y)) {
      diags.error(Code::CurveSyntax, &src, spanOf(st[k]),
                  "a point is two numbers, X Y or X, Y (mm), not '" + std::string(s) + "'");
      ok = false;
      continue;
    }
    if (!(std::abs(x) <= kLargestCurveCoordinate && std::abs(y) <= kLargestCurveCoordinate)) {
      diags.error(Code::CurveSyntax, &src, spanOf(st[k]),
                  "a point beyond 1e6 mm of the origin: Kerf reads curves within a kilometre");
      ok = false;
      continue;
    }
    if (pts.empty() || (pts.back() - geometry::Vec2(x, y)).norm() > 1e-9) pts.emplace_back(x, y);
    if (pts.size() > geometry::kMostFitPoints) {
      diags.error(Code::CurveSyntax, &src, spanOf(st[k]),
                  "more than " + std::to_string(geometry::kMostFitPoints) +
                      " points: Kerf fits a curve through at most that many (split the list)");
      return;
    }
  }
  if (!ok) return;
  if (pts.size() < 2) {
    diags.error(Code::CurveSyntax, &src, spanOf(st.front()), "a point list needs at least two distinct points");
    return;
  }
  const geometry::BiarcFit fit = geometry::fitPointList(pts, bo);
  if (!reportFit(fit, o, src, spanOf(st.front()), diags)) return;
  d.curve = FittedCurve{true, o.tolerance, 0.0, 1.0, fit.spans, fit.maxError};
  fillDrawing(d, fit, "POINTS", spanOf(st.front()), src.locate(st.front().offset).line);
}

/// A parametric curve's three statements.
struct CurveStatements {
  const Statement *x = nullptr, *y = nullptr, *t = nullptr;
};

// ---- 4. parametric curves -----------------------------------------------------------------------

/// x = ..., y = ... and t = ... among the statements, each once; nothing after saying what is
/// wrong or missing.
std::optional<CurveStatements> curveStatements(const SourceFile& src, const std::vector<Statement>& st,
                                               Diagnostics& diags) {
  CurveStatements c;
  bool ok = true;
  for (const Statement& s : st) {
    std::size_t eq = 0;
    const std::string name = nameOf(s.text, eq);
    const Statement** slot = name == "x" ? &c.x : name == "y" ? &c.y : name == "t" ? &c.t : nullptr;
    if (!slot) {
      diags.error(Code::CurveSyntax, &src, spanOf(s),
                  "a curve statement is 'x = EXPR', 'y = EXPR' or 't = FROM : TO', not '" + std::string(s.text) + "'");
      ok = false;
      continue;
    }
    if (*slot) {
      diags.error(Code::CurveSyntax, &src, spanOf(s), "'" + name + "' is given twice");
      ok = false;
      continue;
    }
    *slot = &s;
  }
  if (!ok) return std::nullopt;
  if (!c.x || !c.y || !c.t) {
    diags.error(Code::CurveSyntax, &src, SourceSpan::wholeFile(),
                std::string("the curve has no ") + (!c.x   ? "'x = EXPR'"
                                                    : !c.y ? "'y = EXPR'"
                                                           : "'t = FROM : TO' (--t)"),
                "a curve is x = EXPR; y = EXPR of the parameter t, and its range t = FROM : TO");
    return std::nullopt;
  }
  return c;
}

/// The text after a statement's '=', blanks skipped, and its offset in the file.
std::string_view rightSide(const Statement& s, std::uint32_t& offset) {
  std::size_t eq = 0;
  nameOf(s.text, eq);
  std::string_view r = s.text.substr(eq + 1);
  std::size_t lead = 0;
  while (lead < r.size() && std::isspace(static_cast<unsigned char>(r[lead]))) ++lead;
  offset = s.offset + static_cast<std::uint32_t>(eq + 1 + lead);
  return r.substr(lead);
}

/// The range FROM : TO of the t statement, FROM below TO, both finite; nothing after saying why not.
std::optional<std::pair<double, double>> curveRange(const SourceFile& src, const Statement& ts, Diagnostics& diags) {
  std::uint32_t to = 0;
  const std::string_view tt = rightSide(ts, to);
  const std::size_t colon = tt.find(':');
  if (colon == std::string_view::npos) {
    diags.error(Code::CurveSyntax, &src, spanOf(ts), "the range is 't = FROM : TO', with a colon");
    return std::nullopt;
  }
  Expression from, to2;
  if (!compile(from, tt.substr(0, colon), to, nullptr, src, diags, "the range's start") ||
      !compile(to2, tt.substr(colon + 1), to + static_cast<std::uint32_t>(colon + 1), nullptr, src, diags,
               "the range's end"))
    return std::nullopt;
  const double t0 = eval(from), t1 = eval(to2);
  if (!std::isfinite(t0) || !std::isfinite(t1) || !(t1 > t0)) {
    diags.error(Code::CurveSyntax, &src, spanOf(ts),
                "the range " + formatFixed(t0, 6) + " : " + formatFixed(t1, 6) + " is empty: FROM must be below TO");
    return std::nullopt;
  }
  return std::pair{t0, t1};
}

/// Whether every point of [t0, t1] (probed 2048 times) is finite and within a kilometre; the
/// first that is not is said at its expression.
bool curveIsFinite(const SourceFile& src, CurveState& state, double t0, double t1, Diagnostics& diags) {
  constexpr int kProbes = 2048;
  for (int k = 0; k <= kProbes; ++k) {
    state.t = t0 + (t1 - t0) * k / kProbes;
    const double x = eval(state.x), y = eval(state.y);
    if (!std::isfinite(x) || !std::isfinite(y)) {
      const Expression& bad = std::isfinite(x) ? state.y : state.x;
      diags.error(
          Code::CurveSyntax, &src, {bad.offset, bad.length},
          std::string(std::isfinite(x) ? "y" : "x") + " is not a finite number at t = " + formatFixed(state.t, 6));
      return false;
    }
    if (std::abs(x) > kLargestCurveCoordinate || std::abs(y) > kLargestCurveCoordinate) {
      const Expression& bad = std::abs(x) <= kLargestCurveCoordinate ? state.y : state.x;
      diags.error(Code::CurveSyntax, &src, {bad.offset, bad.length},
                  std::string(std::abs(x) <= kLargestCurveCoordinate ? "y" : "x") + " reaches beyond 1e6 mm at t = " +
                      formatFixed(state.t, 6) + ": Kerf reads curves within a kilometre of the origin");
      return false;
    }
  }
  return true;
}

/// A parametric curve (x = EXPR; y = EXPR; t = FROM : TO) into d: its statements, its range, its
/// expressions compiled and probed, then fitted with biarcs.
void readParametric(const SourceFile& src, const std::vector<Statement>& st, const CurveOptions& o,
                    const geometry::BiarcOptions& bo, Diagnostics& diags, Drawing& d) {
  const std::optional<CurveStatements> c = curveStatements(src, st, diags);
  if (!c) return;
  const std::optional<std::pair<double, double>> range = curveRange(src, *c->t, diags);
  if (!range) return;
  const auto [t0, t1] = *range;
  auto state = std::make_shared<CurveState>();
  state->t = t0;
  std::uint32_t xo = 0, yo = 0;
  const std::string_view xt = rightSide(*c->x, xo), yt = rightSide(*c->y, yo);
  if (!compile(state->x, xt, xo, &state->t, src, diags, "x") || !compile(state->y, yt, yo, &state->t, src, diags, "y"))
    return;
  if (!curveIsFinite(src, *state, t0, t1, diags)) return;
  geometry::ParametricCurve curve;
  curve.point = [state](double t) {
    state->t = t;
    return geometry::Vec2(eval(state->x), eval(state->y));
  };
  curve.t0 = t0;
  curve.t1 = t1;
  const SourceSpan where = spanOf(*c->x);
  const geometry::BiarcFit fit = geometry::fitBiarcs(curve, bo);
  if (!reportFit(fit, o, src, where, diags)) return;
  d.curve = FittedCurve{false, o.tolerance, t0, t1, fit.spans, fit.maxError};
  fillDrawing(d, fit, "CURVE", where, src.locate(c->x->offset).line);
}

}  // namespace

// ---- 5. reading a curve -------------------------------------------------------------------------

Drawing readCurve(const SourceFile& src, const CurveOptions& o, Diagnostics& diags) {
  Drawing d;
  d.version = "curve";
  const std::vector<Statement> st = statements(src.text());
  geometry::BiarcOptions bo;
  bo.tolerance = o.tolerance;
  bo.maxSpans = o.maxSpans;
  std::string first;  // a point list starts with the word `points`
  if (!st.empty())
    for (char c : st.front().text) first += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (first == "points")
    readPointList(src, st, o, bo, diags, d);
  else
    readParametric(src, st, o, bo, diags, d);
  return d;
}

}  // namespace kerf::converter
