#include "occlusion/app/command_line.hpp"

#include <json/writer.h>

#include <cstdio>

#include "occlusion/io/shell_quote.hpp"

namespace occlusion {

namespace {

std::string number_text(const Json::Value& value) {
  if (value.isUInt64()) return std::to_string(value.asUInt64());
  if (value.isInt64()) return std::to_string(value.asInt64());
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value.asDouble());
  return text;
}

std::string compact_json(const Json::Value& value) {
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "";
  return Json::writeString(builder, value);
}

// A word as the CLI's parser reads it (key_sources.cpp): numbers in full,
// lists of scalars comma-joined, objects as JSON text.
std::string word(const Json::Value& value) {
  if (value.isBool()) return value.asBool() ? "true" : "false";
  if (value.isNumeric()) return number_text(value);
  if (value.isString()) return value.asString();
  if (value.isArray()) {
    std::string text;
    for (Json::ArrayIndex i = 0; i < value.size(); ++i) {
      if (value[i].isObject() || value[i].isArray()) return compact_json(value);
      text += (i == 0 ? "" : ",") + word(value[i]);
    }
    return text;
  }
  return compact_json(value);
}

std::string shell_quoted(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_./,:+=@%-") == std::string::npos;
  return plain ? text : shell_quote(text);
}

const KeyInfo* declared(const JobInfo& job, const std::string& name) {
  for (const KeyInfo& info : job.keys) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::string python_value(const Json::Value& value) {
  if (value.isNull()) return "None";
  if (value.isBool()) return value.asBool() ? "True" : "False";
  if (value.isNumeric()) return number_text(value);
  if (value.isString()) return compact_json(value);  // a JSON string is a Python literal
  std::string text = value.isArray() ? "[" : "{";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it, first = false) {
    if (!first) text += ", ";
    if (value.isObject()) text += compact_json(Json::Value(it.name())) + ": ";
    text += python_value(*it);
  }
  return text + (value.isArray() ? "]" : "}");
}

}  // namespace

std::string cli_command(const JobInfo& job, const Json::Value& params) {
  std::string command = "occlusion " + job.cli_names.front();
  if (!job.positional.empty() && params.isMember(job.positional)) {
    const Json::Value& input = params[job.positional];
    if (input.isArray()) {
      for (const auto& item : input) command += " " + shell_quoted(word(item));
    } else {
      command += " " + shell_quoted(word(input));
    }
  }
  for (const std::string& name : params.getMemberNames()) {
    const KeyInfo* info = declared(job, name);
    if (info == nullptr || name == job.positional) continue;
    const Json::Value& value = params[name];
    const std::string flag = " " + cli_spelling(*info);
    if (value.isNull()) {
      if (info->allows_auto) command += flag + " auto";
      continue;
    }
    // A repeatable key takes one item per flag (--viewpoint x,y,z --viewpoint ...).
    if ((info->repeatable || info->type == ValueType::kPointList) && value.isArray()) {
      for (const auto& item : value) command += flag + " " + shell_quoted(word(item));
      continue;
    }
    command += flag + " " + shell_quoted(word(value));
  }
  return command;
}

std::string python_call(const JobInfo& job, const Json::Value& params) {
  std::string call = "occlusion." + job.name + "(";
  bool first = true;
  // The jobs that read a scene take its path as their first argument (`source`).
  const bool source = job.positional == "path" && params.isMember("path");
  if (source) {
    call += python_value(params["path"]);
    first = false;
  }
  for (const std::string& name : params.getMemberNames()) {
    if (declared(job, name) == nullptr || (source && name == "path")) continue;
    call += (first ? "" : ", ") + name + "=" + python_value(params[name]);
    first = false;
  }
  return call + ")";
}

}  // namespace occlusion
