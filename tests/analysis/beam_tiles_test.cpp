// The scanner's tile order, worked by hand: a strip is the grid's rows
// [4 s, 4 s + 4), traced as 8 x 4 tiles row by row within each, every cell
// once, with the narrower tiles at a strip's end and the lower strip at the
// grid's bottom.

#include "occlusion/analysis/beam_tiles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace occlusion {
namespace {

// The cells of tiles [first, last) of the strip, in the order traced.
std::vector<std::size_t> cells(const BeamTiles& tiles, std::size_t strip, std::size_t first,
                               std::size_t last) {
  std::vector<std::size_t> out;
  tiles.visit(strip, first, last, [&](std::size_t row, std::size_t column) {
    out.push_back(row * tiles.columns + column);
  });
  return out;
}

TEST(BeamTiles, AStripIsItsRowsTracedTileByTile) {
  const BeamTiles tiles{19, 7};  // tiles of 8, 8 and 3 columns; strips of 4 and 3 rows
  ASSERT_EQ(tiles.strips(), 2u);
  ASSERT_EQ(tiles.tiles_per_strip(), 3u);
  EXPECT_EQ(tiles.first_cell(0), 0u);
  EXPECT_EQ(tiles.first_cell(1), 4u * 19u);
  EXPECT_EQ(tiles.first_cell(2), 7u * 19u);
  // The first tile: columns 0..7 of row 0, then of rows 1, 2 and 3.
  const std::vector<std::size_t> first = cells(tiles, 0, 0, 1);
  ASSERT_EQ(first.size(), 32u);
  for (std::size_t p = 0; p < 32; ++p) EXPECT_EQ(first[p], p / 8 * 19 + p % 8) << p;
  // The last tile of the strip is 3 columns wide: 16, 17, 18 of each row.
  const std::vector<std::size_t> last = cells(tiles, 0, 2, 3);
  EXPECT_EQ(last, (std::vector<std::size_t>{16, 17, 18, 35, 36, 37, 54, 55, 56, 73, 74, 75}));
  // The bottom strip's tiles are 3 rows high.
  const std::vector<std::size_t> bottom = cells(tiles, 1, 1, 2);
  ASSERT_EQ(bottom.size(), 24u);
  EXPECT_EQ(bottom.front(), 4u * 19u + 8u);
  EXPECT_EQ(bottom[8], 5u * 19u + 8u);
  EXPECT_EQ(bottom.back(), 6u * 19u + 15u);
}

TEST(BeamTiles, EveryCellIsTracedOnceInItsOwnStrip) {
  for (const auto& [columns, rows] : std::vector<std::pair<std::size_t, std::size_t>>{
           {1, 1}, {8, 4}, {19, 7}, {3600, 9}, {5, 13}}) {
    const BeamTiles tiles{columns, rows};
    std::vector<int> seen(columns * rows, 0);
    for (std::size_t s = 0; s < tiles.strips(); ++s) {
      for (const std::size_t cell : cells(tiles, s, 0, tiles.tiles_per_strip())) {
        ASSERT_GE(cell, tiles.first_cell(s));
        ASSERT_LT(cell, tiles.first_cell(s + 1));
        ++seen[cell];
      }
    }
    EXPECT_EQ(tiles.first_cell(tiles.strips()), columns * rows);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size()))
        << columns << " x " << rows;
  }
}

}  // namespace
}  // namespace occlusion
