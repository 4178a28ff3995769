// `kerf check --format html` (html_report.h).
#include "kerf/converter/report/html_report.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/report/html.h"

#include <set>

namespace kerf::converter {
namespace {

constexpr std::string_view kStyle =
    "body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222}"
    "table{border-collapse:collapse}th,td{padding:.25em .6em;border-bottom:1px solid #ddd;text-align:left}"
    "th{cursor:pointer;background:#f4f4f4}td.n{text-align:right}"
    ".ok{color:#17643a}.errors{color:#b00020}.unread{color:#8a5a00}"
    "pre{background:#f8f8f8;padding:.8em;overflow-x:auto}";

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

std::string row(const HtmlReportEntry& e) {
  std::string r = "<tr><td><a href=\"" + markupText(e.page) + "\">" + markupText(e.name) + "</a></td><td class=\"" +
                  verdictClass(e.exit) + "\" data-value=\"" + std::to_string(e.exit) + "\">" + verdictWord(e.exit) +
                  "</td>" + number(std::to_string(e.errors), static_cast<double>(e.errors)) +
                  number(std::to_string(e.warnings), static_cast<double>(e.warnings)) +
                  number(std::to_string(e.notes), static_cast<double>(e.notes));
  if (!e.summary) return r + "<td colspan=\"5\">" + markupText(e.failure) + "</td></tr>\n";
  const Summary& s = *e.summary;
  const double minutes = s.structure.time.total();
  r += "<td>" + markupText(dialectName(s.dialect)) + "</td><td>" + markupText(s.reading.machine) + "</td>" +
       number(std::to_string(passCount(s)), static_cast<double>(passCount(s))) +
       number(formatFixed(s.cutLength, 3) + " mm", s.cutLength) +
       (minutes > 0 ? number(formatFixed(minutes, 2) + " min", minutes) : std::string("<td class=\"n\"></td>"));
  return r + "</tr>\n";
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
    std::string name = base + ".html";
    for (int k = 2; !used.insert(name).second; ++k) name = base + "-" + std::to_string(k) + ".html";
    names.push_back(name);
  }
  return names;
}

std::string htmlReportIndex(std::span<const HtmlReportEntry> entries, const std::string& summaryLine) {
  std::string body = "<h1>Kerf check</h1>\n<p>" + markupText(summaryLine) +
                     "</p>\n<table>\n<thead><tr><th>program</th><th>verdict</th><th>errors</th><th>warnings</th>"
                     "<th>notes</th><th>dialect</th><th>machine</th><th>passes</th><th>cut length</th>"
                     "<th>time</th></tr></thead>\n<tbody>\n";
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
  if (!e.summaryText.empty()) body += "<h2>Summary</h2>\n<pre>" + markupText(e.summaryText) + "</pre>\n";
  body += "<h2>Diagnostics</h2>\n";
  body +=
      e.diagnosticsText.empty() ? std::string("<p>none</p>\n") : "<pre>" + markupText(e.diagnosticsText) + "</pre>\n";
  return page(e.name + " — Kerf check", body, false);
}

}  // namespace kerf::converter
