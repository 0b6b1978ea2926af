#include "occlusion/io/face_table.hpp"

#include <ostream>
#include <stdexcept>

#include "number_text.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/csv_file.hpp"

namespace occlusion {

namespace {

constexpr int kSignificantDigits = 9;
// Rows are formatted into a buffer of about this size, then written: a
// stream's own number formatting took a third of -moc's writing.
constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

}  // namespace

void write_face_table(const std::string& path, const TriangleMesh& mesh,
                      const std::vector<std::size_t>& samples,
                      const std::vector<float>& visible_fraction) {
  const std::size_t faces = mesh.face_count();
  if (samples.size() != faces || visible_fraction.size() != faces) {
    throw std::invalid_argument("write_face_table: " + std::to_string(samples.size()) +
                                " sample counts and " + std::to_string(visible_fraction.size()) +
                                " fractions for " + std::to_string(faces) + " faces");
  }
  std::vector<std::string> group_fields;
  group_fields.reserve(mesh.group_names.size());
  for (const std::string& name : mesh.group_names) group_fields.push_back(csv_field(name));

  write_file_atomically(path, [&](std::ostream& out) {
    std::string text = "face,group,area,samples,visible_fraction\n";
    text.reserve(kFlushBytes + 256);
    for (std::size_t f = 0; f < faces; ++f) {
      detail::append_number(text, f);
      text += ',';
      text += group_fields.at(mesh.face_group[f]);
      text += ',';
      detail::append_significant(text, mesh.face_area(f), kSignificantDigits);
      text += ',';
      detail::append_number(text, samples[f]);
      text += ',';
      detail::append_significant(text, static_cast<double>(visible_fraction[f]),
                                 kSignificantDigits);
      text += '\n';
      if (text.size() >= kFlushBytes) {
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        text.clear();
      }
    }
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

}  // namespace occlusion
