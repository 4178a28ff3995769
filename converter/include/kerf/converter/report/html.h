// Building blocks of Kerf's HTML pages (the CI report and the 3D page, issue 57) and of its XML
// (JUnit): whatever comes from the input (a program's text and comments, a file name, a diagnostic
// that quotes them) is data, never markup. Each function states where its result may be put.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace kerf::converter {

/// Text for an element's content or a double- or single-quoted attribute value, in HTML or XML 1.0
/// (the JUnit report): `& < > " '` as character references; a byte sequence that is not UTF-8 (a
/// Shift-JIS comment, a stray byte), and a control character other than tab, line feed and
/// carriage return (which XML 1.0 does not allow), as U+FFFD. Never markup, whatever the input.
std::string markupText(std::string_view text);

/// A JSON text made safe inside `<script type="application/json">` (read back with JSON.parse):
/// `<`, `>` and `&` as `\u003c` `\u003e` `\u0026` (they can stand in a JSON text only inside its
/// strings, where the escape means the same), U+2028 and U+2029 as `\u2028` `\u2029`. So no input
/// closes the script element or opens a comment in it. The text must be JSON (nlohmann-json's dump
/// with its UTF-8 replacement).
std::string scriptJson(std::string_view json);

/// A page's title for a program named `name` (a path): its file name, cut to 48 bytes (on a UTF-8
/// character's boundary, "…" added), then `suffix`. Markup is not escaped here.
std::string programTitle(std::string_view name, std::string_view suffix);

/// SHA-256 of the bytes (FIPS 180-4).
std::array<std::uint8_t, 32> sha256(std::string_view bytes);

/// Standard base64 (RFC 4648, with padding).
std::string base64(std::span<const std::uint8_t> bytes);

/// A Content-Security-Policy for a page whose only scripts and styles are the embedded ones given:
/// nothing from the network, no other script or style (an injected one does not run), images only
/// from data: URLs and the page's own folder. For the double-quoted content attribute of a
/// `<meta http-equiv="Content-Security-Policy">` (the result holds no double quote). scriptFiles:
/// the page's scripts are files of its own folder instead (`script-src 'self'`: a report's pages
/// share one copy of a large script), `scripts` unused.
std::string contentSecurityPolicy(std::span<const std::string_view> scripts, std::span<const std::string_view> styles,
                                  bool scriptFiles = false);

}  // namespace kerf::converter
