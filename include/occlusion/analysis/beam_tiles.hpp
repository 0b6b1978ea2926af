#pragma once
// The order the virtual scanner traces a station's beams in. Its grid
// (columns x rows: a laser's azimuth and elevation steps, a camera's pixels;
// cell = row * columns + column) is cut into strips of kRows rows and each
// strip into tiles of kColumns columns; the beams go tile after tile, row by
// row within a tile. A tile's beams point within a few steps of each other,
// so its 32 rays go down the triangle octree as one packet
// (BatchOrder::kAsGiven) and part late, where the grid's own order puts 32
// beams of one row side by side and sorting them by direction costs a pass
// of its own (bench/README.md, bench_simulate). A strip is a contiguous range
// of cells, so its returns join the cloud in the grid's order.

#include <algorithm>
#include <cstddef>

namespace occlusion {

struct BeamTiles {
  static constexpr std::size_t kColumns = 8, kRows = 4;

  std::size_t columns = 0, rows = 0;

  std::size_t strips() const { return (rows + kRows - 1) / kRows; }
  std::size_t tiles_per_strip() const { return (columns + kColumns - 1) / kColumns; }
  // Strip s holds cells [first_cell(s), first_cell(s + 1)).
  std::size_t first_cell(std::size_t strip) const {
    return std::min(rows, strip * kRows) * columns;
  }
  // visit(row, column) for each beam of tiles [first_tile, last_tile) of the
  // strip, in the order they are traced (no division per beam: the scanner
  // aims millions).
  template <class Visit>
  void visit(std::size_t strip, std::size_t first_tile, std::size_t last_tile,
             Visit&& visit) const {
    const std::size_t first_row = strip * kRows;
    const std::size_t last_row = std::min(rows, first_row + kRows);
    for (std::size_t tile = first_tile; tile < last_tile; ++tile) {
      const std::size_t first_column = tile * kColumns;
      const std::size_t last_column = std::min(columns, first_column + kColumns);
      for (std::size_t row = first_row; row < last_row; ++row) {
        for (std::size_t column = first_column; column < last_column; ++column) {
          visit(row, column);
        }
      }
    }
  }
};

}  // namespace occlusion
