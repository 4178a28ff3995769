// The comparison of two parses of one text (in one pass and in parts) that the parser's unit test
// and the fuzz target share.
#pragma once

#include "kerf/converter/program.h"

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

namespace kerf::test {

/// "" when b is a's program, else what differs first: the same blocks, each with the same words
/// (b's words may lie at other indices: the parser moves a later part's words to the next 2 MiB
/// page, and the indices between, which no block names, must hold empty words), the same blocks
/// not plain, settings, heights and figures of the integers.
inline std::string parseDifference(const converter::Program& a, const converter::Program& b) {
  const auto sameBits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  if (a.blocks.size() != b.blocks.size())
    return std::to_string(a.blocks.size()) + " blocks against " + std::to_string(b.blocks.size());
  std::vector<bool> named(b.words.size(), false);
  for (std::size_t k = 0; k < a.blocks.size(); ++k) {
    const converter::Block &x = a.blocks[k], &y = b.blocks[k];
    if (x.wordCount != y.wordCount || x.offset != y.offset || x.length != y.length || x.line != y.line ||
        x.upperFrom != y.upperFrom || x.kind != y.kind || x.colon != y.colon || x.hasError != y.hasError ||
        x.plain != y.plain)
      return "block " + std::to_string(k);
    if (std::size_t{y.firstWord} + y.wordCount > b.words.size()) return "block " + std::to_string(k) + "'s words";
    for (std::size_t w = 0; w < x.wordCount; ++w) {
      const converter::Word &u = a.words[x.firstWord + w], &v = b.words[y.firstWord + w];
      if (u.letter != v.letter || u.offset != v.offset || u.length != v.length || u.hasPoint != v.hasPoint ||
          u.kind != v.kind || !sameBits(u.value, v.value))
        return "block " + std::to_string(k) + ", word " + std::to_string(w);
      named[y.firstWord + w] = true;
    }
  }
  std::size_t unnamed = 0;
  for (std::size_t k = 0; k < b.words.size(); ++k)
    if (!named[k]) {
      ++unnamed;
      if (b.words[k].letter != 0) return "word " + std::to_string(k) + " lies between parts and is not empty";
    }
  if (a.words.size() + unnamed != b.words.size()) return "a word that no block names";
  if (a.notPlain != b.notPlain) return "the blocks not plain";
  if (a.settings.size() != b.settings.size()) return "the settings' count";
  for (std::size_t k = 0; k < a.settings.size(); ++k)
    if (a.settings[k].name != b.settings[k].name || a.settings[k].value != b.settings[k].value ||
        a.settings[k].line != b.settings[k].line)
      return "setting " + std::to_string(k);
  if (a.heights.size() != b.heights.size()) return "the heights' count";
  for (std::size_t k = 0; k < a.heights.size(); ++k)
    if (!sameBits(a.heights[k].value, b.heights[k].value) || a.heights[k].line != b.heights[k].line)
      return "height " + std::to_string(k);
  if (a.anyDecimalPoint != b.anyDecimalPoint || !sameBits(a.largestInteger, b.largestInteger) ||
      a.integerLengthWords != b.integerLengthWords)
    return "the figures of the integers";
  if (!a.words.empty() && !b.words.empty() &&
      a.words[a.largestIntegerWord].offset != b.words[b.largestIntegerWord].offset)
    return "the largest integer's word";
  return "";
}

}  // namespace kerf::test
