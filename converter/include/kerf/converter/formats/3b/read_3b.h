// The 3B reader (docs/3b.md, FORMATS §4): Chinese fast-wire 3B code to a Toolpath, one Move per
// record, each with the span of its record.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/toolpath.h"

#include <string>
#include <string_view>

namespace kerf::converter {

struct ThreeBOptions {
  geometry::Vec2 start{0, 0};  ///< where the first record starts (3B is relative), mm
};

/// Reads 3B code (docs/3b.md): records `B x B y B J G Z` token by token, with or without line
/// breaks between them, any spacing, empty fields (0), lower case, `;` comments to the end of the
/// line, and `DD` or `FF` as the end. A malformed record is an error at its line and column and
/// moves nothing; reading goes on at the next line. The result's blocks count the records.
Toolpath readThreeB(const SourceFile& source, const ThreeBOptions& options, Diagnostics& diags);

/// The first record of a text that is 3B code (a B field first, after blanks and `;` comments, and
/// a count direction GX or GY within the first 4 KB), at most 40 characters; empty otherwise.
std::string firstThreeBRecord(std::string_view text);

}  // namespace kerf::converter
