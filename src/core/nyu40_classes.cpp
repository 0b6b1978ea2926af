#include "occlusion/core/nyu40_classes.hpp"

namespace occlusion {

const std::vector<std::string>& nyu40_class_names() {
  static const std::vector<std::string> names = {
      "unannotated", "wall",    "floor",       "cabinet",        "bed",
      "chair",       "sofa",    "table",       "door",           "window",
      "bookshelf",   "picture", "counter",     "blinds",         "desk",
      "shelves",     "curtain", "dresser",     "pillow",         "mirror",
      "floor mat",   "clothes", "ceiling",     "books",          "refridgerator",
      "television",  "paper",   "towel",       "shower curtain", "box",
      "whiteboard",  "person",  "night stand", "toilet",         "sink",
      "lamp",        "bathtub", "bag",         "otherstructure", "otherfurniture",
      "otherprop"};
  return names;
}

const std::array<ScanNetBenchmarkClass, 20>& scannet20_classes() {
  static const std::array<ScanNetBenchmarkClass, 20> classes = {
      {{1, "wall"},    {2, "floor"},      {3, "cabinet"},       {4, "bed"},
       {5, "chair"},   {6, "sofa"},       {7, "table"},         {8, "door"},
       {9, "window"},  {10, "bookshelf"}, {11, "picture"},      {12, "counter"},
       {14, "desk"},   {16, "curtain"},   {24, "refrigerator"}, {28, "shower curtain"},
       {33, "toilet"}, {34, "sink"},      {36, "bathtub"},      {39, "otherfurniture"}}};
  return classes;
}

}  // namespace occlusion
