// `kerf check --format html` (html_report.h).
#include "kerf/converter/report/html_report.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/report/html.h"
#include "kerf/converter/structure/passes.h"

#include <set>

namespace kerf::converter {
namespace {

constexpr std::string_view kStyle =
    "body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222}"
    "table{border-collapse:collapse}th,td{padding:.25em .6em;border-bottom:1px solid #ddd;text-align:left}"
    "th{cursor:pointer;background:#f4f4f4}td.n{text-align:right}"
    ".ok{color:#17643a}.errors{color:#b00020}.unread{color:#8a5a00}"
    "pre{background:#f8f8f8;padding:.8em;overflow-x:auto}"
    "td img{display:block;border:1px solid #ddd;margin-bottom:.2em}figure{display:inline-block;margin:0 1em 1em 0}"
    "figure img{border:1px solid #ddd}.over{color:#b00020;font-weight:bold}";

// Sorts the index by the column clicked (numbers as numbers), and marks the page as ready: a test
// in a browser reads the mark to know the Content-Security-Policy let the script run.
constexpr std::string_view kSortScript =
    "document.querySelectorAll('th').forEach((th,col)=>th.addEventListener('click',()=>{"
    "const body=document.querySelector('tbody');const rows=Array.from(body.rows);"
    "const asc=th.dataset.order!=='asc';"
    "document.querySelectorAll('th').forEach(h=>delete h.dataset.order);th.dataset.order=asc?'asc':'desc';"
    "const key=r=>r.cells[col].dataset.value??r.cells[col].textContent;"
    "rows.sort((a,b)=>{const x=key(a),y=key(b),nx=parseFloat(x),ny=parseFloat(y);"
    "const c=!isNaN(nx)&&!isNaN(ny)?nx-ny:x.localeCompare(y);return asc?c:-c;});"
    "rows.forEach(r=>body.appendChild(r));}));"
    "document.documentElement.dataset.ready='1';";

/// A whole page: its policy allows the embedded style and, for the index, the one script. The
/// policies are made once (the hashes of constant texts).
std::string page(const std::string& title, const std::string& body, bool sortable) {
  static const std::string_view styles[] = {kStyle};
  static const std::string plainPolicy = contentSecurityPolicy({}, styles);
  static const std::string sortPolicy = contentSecurityPolicy(std::span(&kSortScript, 1), styles);
  const std::string& csp = sortable ? sortPolicy : plainPolicy;
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"" +
      csp + "\">\n<title>" + markupText(title) + "</title>\n<style>" + std::string(kStyle) +
      "</style>\n</head>\n<body>\n" + body;
  if (sortable) html += "<script>" + std::string(kSortScript) + "</script>\n";
  return html + "</body>\n</html>\n";
}

const char* verdictWord(int exit) { return exit == 0 ? "ok" : exit == 1 ? "errors" : "not read"; }
const char* verdictClass(int exit) { return exit == 0 ? "ok" : exit == 1 ? "errors" : "unread"; }

std::size_t passCount(const Summary& s) {
  std::size_t n = 0;
  for (const Contour& c : s.structure.contours) n += c.passes.size();
  return n;
}

/// A numeric cell: the text shown, and the value sorted by.
std::string number(const std::string& shown, double value) {
  return "<td class=\"n\" data-value=\"" + formatFixed(value, 6) + "\">" + markupText(shown) + "</td>";
}

/// The program's cell: its picture (when made) and its name, a link to its page.
std::string programCell(const HtmlReportEntry& e) {
  std::string cell = "<td><a href=\"" + markupText(e.page) + "\">";
  if (!e.thumbnail.empty())
    cell += "<img src=\"" + markupText(e.thumbnail) + "\" width=\"160\" height=\"120\" alt=\"\">";
  return cell + markupText(e.name) + "</a></td>";
}

std::string deviationCell(const HtmlReportEntry& e) {
  if (!e.worstDeviation) return "<td class=\"n\"></td>";
  const bool over = e.tolerance && *e.worstDeviation > *e.tolerance;
  return "<td class=\"n" + std::string(over ? " over" : "") + "\" data-value=\"" + formatFixed(*e.worstDeviation, 6) +
         "\">" + formatFixed(*e.worstDeviation, 4) + " mm</td>";
}

std::string row(const HtmlReportEntry& e) {
  std::string r = "<tr>" + programCell(e) + "<td class=\"" + verdictClass(e.exit) + "\" data-value=\"" +
                  std::to_string(e.exit) + "\">" + verdictWord(e.exit) + "</td>" +
                  number(std::to_string(e.errors), static_cast<double>(e.errors)) +
                  number(std::to_string(e.warnings), static_cast<double>(e.warnings)) +
                  number(std::to_string(e.notes), static_cast<double>(e.notes));
  if (!e.summary) return r + "<td colspan=\"6\">" + markupText(e.failure) + "</td></tr>\n";
  const Summary& s = *e.summary;
  const double minutes = s.structure.time.total();
  r += "<td>" + markupText(dialectName(s.dialect)) + "</td><td>" + markupText(s.reading.machine) + "</td>" +
       number(std::to_string(passCount(s)), static_cast<double>(passCount(s))) +
       number(formatFixed(s.cutLength, 3) + " mm", s.cutLength) +
       (minutes > 0 ? number(formatFixed(minutes, 2) + " min", minutes) : std::string("<td class=\"n\"></td>")) +
       deviationCell(e);
  return r + "</tr>\n";
}

/// The passes of each contour: what each is, its offset, its lines, its length and time.
std::string passTable(const Structure& structure) {
  std::string t =
      "<table>\n<thead><tr><th>pass</th><th>what</th><th>offset</th><th>condition</th><th>lines</th>"
      "<th>length</th><th>time</th></tr></thead>\n<tbody>\n";
  for (std::size_t c = 0; c < structure.contours.size(); ++c)
    for (std::size_t k = 0; k < structure.contours[c].passes.size(); ++k) {
      const Pass& p = structure.contours[c].passes[k];
      t += "<tr><td>" + passName(c, k) + "</td><td>" + passRole(p, k) + "</td><td>" + markupText(offsetText(p)) +
           "</td><td>" + markupText(p.condition) + "</td><td>" + std::to_string(p.firstLine) + "–" +
           std::to_string(p.lastLine) + "</td>" + number(formatFixed(p.length, 3) + " mm", p.length) +
           (p.minutes ? number(formatFixed(*p.minutes, 2) + " min", *p.minutes) : std::string("<td></td>")) + "</tr>\n";
    }
  return t + "</tbody>\n</table>\n";
}

/// The part from above and in iso, and the link to its 3D page.
std::string views(const HtmlReportEntry& e) {
  std::string v;
  for (const auto& [file, caption] : {std::pair{&e.top, "from above"}, std::pair{&e.iso, "iso"}})
    if (!file->empty())
      v += "<figure><img src=\"" + markupText(*file) + "\" width=\"480\" height=\"360\" alt=\"the part " + caption +
           "\"><figcaption>" + caption + "</figcaption></figure>\n";
  if (!e.page3d.empty())
    v += "<p><a href=\"" + markupText(e.page3d) + "\">the part in 3D, beside the program</a></p>\n";
  return v;
}

}  // namespace

std::vector<std::string> htmlPageNames(std::span<const std::string> programs) {
  std::vector<std::string> names;
  std::set<std::string> used = {"index.html"};
  for (const std::string& p : programs) {
    const std::size_t slash = p.find_last_of('/');
    std::string base = slash == std::string::npos ? p : p.substr(slash + 1);
    for (char& c : base) {
      const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                        c == '_' || c == '-';
      if (!safe) c = '_';
    }
    if (base.empty() || base.front() == '.') base.insert(0, "program");
    // A page <stem>.html keeps <stem>.3d.html for its 3D page: neither may be another's.
    std::string stem = base;
    for (int k = 2; used.count(stem + ".html") || used.count(stem + ".3d.html"); ++k)
      stem = base + "-" + std::to_string(k);
    used.insert(stem + ".3d.html");
    used.insert(stem + ".html");
    names.push_back(stem + ".html");
  }
  return names;
}

std::string htmlReportIndex(std::span<const HtmlReportEntry> entries, const std::string& summaryLine,
                            const std::string& note) {
  std::string body = "<h1>Kerf check</h1>\n<p>" + markupText(summaryLine) + "</p>\n";
  if (!note.empty()) body += "<p>" + markupText(note) + "</p>\n";
  body +=
      "<table>\n<thead><tr><th>program</th><th>verdict</th><th>errors</th><th>warnings</th>"
      "<th>notes</th><th>dialect</th><th>machine</th><th>passes</th><th>cut length</th>"
      "<th>time</th><th>drawing</th></tr></thead>\n<tbody>\n";
  for (const HtmlReportEntry& e : entries) body += row(e);
  body += "</tbody>\n</table>\n";
  return page("Kerf check", body, true);
}

std::string htmlReportPage(const HtmlReportEntry& e) {
  std::string body = "<p><a href=\"index.html\">all programs</a></p>\n<h1>" + markupText(e.name) +
                     "</h1>\n<p class=\"" + verdictClass(e.exit) + "\">verdict: " + verdictWord(e.exit) + " (" +
                     std::to_string(e.errors) + " errors, " + std::to_string(e.warnings) + " warnings, " +
                     std::to_string(e.notes) + " notes)</p>\n";
  if (!e.failure.empty()) body += "<p>" + markupText(e.failure) + "</p>\n";
  body += views(e);
  if (!e.summaryText.empty()) body += "<h2>Summary</h2>\n<pre>" + markupText(e.summaryText) + "</pre>\n";
  if (e.summary && !e.summary->structure.contours.empty())
    body += "<h2>Passes</h2>\n" + passTable(e.summary->structure);
  body += "<h2>Diagnostics</h2>\n";
  body +=
      e.diagnosticsText.empty() ? std::string("<p>none</p>\n") : "<pre>" + markupText(e.diagnosticsText) + "</pre>\n";
  return page(programTitle(e.name, " — Kerf check"), body, false);
}

}  // namespace kerf::converter
