// The building blocks of Kerf's HTML pages (report/html.h): hostile input stays text, JSON in a
// script cannot close it, and the CSP hashes are SHA-256 as FIPS 180-4's examples give them.
#include "kerf/converter/report/html.h"
#include "kerf/converter/report/html_report.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using kerf::converter::base64;
using kerf::converter::contentSecurityPolicy;
using kerf::converter::htmlPageNames;
using kerf::converter::markupText;
using kerf::converter::programTitle;
using kerf::converter::scriptJson;
using kerf::converter::sha256;

std::string hex(const std::array<std::uint8_t, 32>& d) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s;
  for (const std::uint8_t b : d) s += std::string{kDigits[b >> 4], kDigits[b & 15]};
  return s;
}

// A comment that closes a script, an event handler, a file name with angle brackets: all text.
TEST(html_test, markup_from_the_input_is_text) {
  EXPECT_EQ(markupText("(</script><script>alert(1)</script>)"),
            "(&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;)");
  EXPECT_EQ(markupText("<img src=x onerror=\"alert('x')\">"),
            "&lt;img src=x onerror=&quot;alert(&#39;x&#39;)&quot;&gt;");
  EXPECT_EQ(markupText("a<b>x.nc & more"), "a&lt;b&gt;x.nc &amp; more");
  EXPECT_EQ(markupText("G01 X1.\tY2.\r\n"), "G01 X1.\tY2.\r\n");  // the program's own whitespace kept
}

// Bytes that are not UTF-8 (a Shift-JIS comment read as bytes, a cut sequence, an overlong '<',
// a surrogate) and control characters become U+FFFD; UTF-8 passes as it is.
TEST(html_test, bytes_that_are_not_text_are_replaced) {
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(markupText("\x83\x65"), fffd + "e");              // Shift-JIS's katakana te: a lead byte, then ASCII 'e'
  EXPECT_EQ(markupText("\xC0\xBC"), fffd + fffd);             // an overlong '<'
  EXPECT_EQ(markupText("\xED\xA0\x80"), fffd + fffd + fffd);  // a surrogate
  EXPECT_EQ(markupText("\xE2\x82"), fffd + fffd);             // cut short
  EXPECT_EQ(markupText(std::string("a\0b\x1b", 4)), "a" + fffd + "b" + fffd);
  EXPECT_EQ(markupText("Ø 20 µm — 60°"), "Ø 20 µm — 60°");
}

TEST(html_test, json_in_a_script_cannot_close_it) {
  const std::string json = R"({"comment":"</script><!-- & \u2028","line":"a)"
                           "\xE2\x80\xA8"
                           R"(b"})";
  const std::string safe = scriptJson(json);
  EXPECT_EQ(safe.find('<'), std::string::npos);
  EXPECT_EQ(safe.find('>'), std::string::npos);
  EXPECT_EQ(safe.find('&'), std::string::npos);
  EXPECT_EQ(safe.find("\xE2\x80\xA8"), std::string::npos);
  EXPECT_EQ(safe, R"({"comment":"\u003c/script\u003e\u003c!-- \u0026 \u2028","line":"a\u2028b"})");
}

// FIPS 180-4's examples (and NIST's one-million-'a' message).
TEST(html_test, sha256_of_the_standard_examples) {
  EXPECT_EQ(hex(sha256("")), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(hex(sha256("abc")), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(hex(sha256("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(hex(sha256(std::string(1000000, 'a'))), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // 55, 56 and 64 bytes, the padding's edge cases (the digests Python's hashlib gives).
  EXPECT_EQ(hex(sha256(std::string(55, 'a'))), "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  EXPECT_EQ(hex(sha256(std::string(56, 'a'))), "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
  EXPECT_EQ(hex(sha256(std::string(64, 'a'))), "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
}

TEST(html_test, base64_and_the_policy) {
  const std::uint8_t bytes[] = {'M', 'a', 'n'};
  EXPECT_EQ(base64(std::span(bytes, 3)), "TWFu");
  EXPECT_EQ(base64(std::span(bytes, 2)), "TWE=");
  EXPECT_EQ(base64(std::span(bytes, 1)), "TQ==");
  EXPECT_EQ(base64(sha256("abc")), "ungWv48Bz+pBQUDeXa4iI7ADYaOWF3qctBD/YfIAFa0=");
  const std::string_view scripts[] = {"abc"};
  const std::string csp = contentSecurityPolicy(scripts, {});
  EXPECT_EQ(csp,
            "default-src 'none'; script-src 'sha256-ungWv48Bz+pBQUDeXa4iI7ADYaOWF3qctBD/YfIAFa0='; style-src 'none'; "
            "img-src 'self' data:; base-uri 'none'; form-action 'none'");
  EXPECT_EQ(csp.find('"'), std::string::npos);
  // A report's 3D pages load their scripts from the folder: 'self', no hash.
  EXPECT_EQ(contentSecurityPolicy(scripts, {}, true).find("script-src 'self'; style-src 'none'"), 20u);
}

// Page names: safe bytes, unique, never the index, and each page's <stem>.3d.html free for its 3D
// page (a program named "a.3d" must not take program a's).
TEST(html_test, page_names_leave_room_for_3d_pages) {
  const std::string programs[] = {"dir/a", "a.3d", "other/a", "index", "x<y>.nc", ".hidden"};
  const std::vector<std::string> names = htmlPageNames(programs);
  ASSERT_EQ(names.size(), 6u);
  EXPECT_EQ(names[0], "a.html");
  EXPECT_EQ(names[1], "a.3d-2.html");
  EXPECT_EQ(names[2], "a-2.html");
  EXPECT_EQ(names[3], "index-2.html");
  EXPECT_EQ(names[4], "x_y_.nc.html");
  EXPECT_EQ(names[5], "program.hidden.html");
}

// A title: the file's name, not its folders, cut on a character's boundary.
TEST(html_test, program_titles_are_short) {
  EXPECT_EQ(programTitle("../shared/realworld/iso2d/part.nc", " — Kerf"), "part.nc — Kerf");
  const std::string long_name = std::string(47, 'x') + "\xc3\xa9" + "tail.nc";  // é across byte 48
  EXPECT_EQ(programTitle(long_name, ""), std::string(47, 'x') + "…");
}

}  // namespace
