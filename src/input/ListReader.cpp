#include "ListReader.hpp"

#include <algorithm>
#include <sstream>

#include "core/InputError.hpp"

namespace pf {

namespace {

bool isInt(const Teuchos::ParameterEntry& e) { return e.isType<int>() || e.isType<long long>(); }

bool matches(const Teuchos::ParameterEntry& e, ParameterSpec::Kind k) {
  switch (k) {
    case ParameterSpec::Kind::Double: return e.isType<double>() || isInt(e);
    case ParameterSpec::Kind::Int: return isInt(e);
    case ParameterSpec::Kind::Bool: return e.isType<bool>();
    case ParameterSpec::Kind::String: return e.isType<std::string>();
    case ParameterSpec::Kind::Scalar: return e.isType<std::string>() || e.isType<double>() || isInt(e);
  }
  return false;
}

const ParameterSpec* findSpec(const std::vector<ParameterSpec>& specs, const std::string& name) {
  for (const ParameterSpec& s : specs)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace

void fail(const std::string& file, const std::string& path, const std::string& msg) {
  throw InputError(file + ": " + path + ": " + msg);
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out;
}

std::string numberText(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void checkList(const PL& l, const std::vector<ParameterSpec>& specs, const std::vector<std::string>& sublists,
               const std::string& file, const std::string& path) {
  for (auto it = l.begin(); it != l.end(); ++it) {
    const std::string& name = l.name(it);
    const Teuchos::ParameterEntry& e = l.entry(it);
    if (e.isList()) {
      if (std::find(sublists.begin(), sublists.end(), name) == sublists.end())
        fail(file, path, "unknown sub-list '" + name + "'" +
                             (sublists.empty() ? std::string() : " (allowed: " + joinNames(sublists) + ")"));
      continue;
    }
    const ParameterSpec* s = findSpec(specs, name);
    if (!s) {
      std::vector<std::string> allowed;
      for (const ParameterSpec& q : specs) allowed.push_back(q.name);
      fail(file, path, "unknown parameter '" + name + "'" +
                           (allowed.empty() ? std::string() : " (allowed: " + joinNames(allowed) + ")"));
    }
    if (!matches(e, s->kind))
      fail(file, path, "'" + name + "' must be a " + kindName(s->kind) + " (got " + e.getAny().typeName() + ")");
  }
  for (const ParameterSpec& s : specs)
    if (s.required && !l.isParameter(s.name)) fail(file, path, "missing required parameter '" + s.name + "'");
}

ParameterValues readList(const PL& l, const std::vector<ParameterSpec>& specs, const std::vector<std::string>& sublists,
                         const std::string& file, const std::string& path) {
  checkList(l, specs, sublists, file, path);
  ParameterValues in;
  const std::size_t slash = path.find_last_of('/');
  in.name = slash == std::string::npos ? path : path.substr(slash + 1);
  in.inputFile = file;
  in.path = path;
  for (auto it = l.begin(); it != l.end(); ++it) {
    const std::string& name = l.name(it);
    const Teuchos::ParameterEntry& e = l.entry(it);
    if (e.isList()) continue;
    const ParameterSpec& s = *findSpec(specs, name);
    if (e.isType<bool>())
      in.values[name] = Teuchos::getValue<bool>(e) ? 1.0 : 0.0;
    else if (e.isType<std::string>() || s.kind == ParameterSpec::Kind::Scalar)
      in.strings[name] = scalarAsText(e);
    else
      in.values[name] = getNumber(l, name);
  }
  applySpecs(specs, in);  // ranges, choices and defaults
  return in;
}

const PL& requireSublist(const PL& l, const std::string& name, const std::string& file, const std::string& path) {
  if (!l.isSublist(name)) fail(file, path, "missing required sub-list '" + name + "'");
  return l.sublist(name);
}

std::vector<std::string> numberedLists(const PL& deck, const std::string& stem) {
  std::vector<std::string> out;
  if (deck.isSublist(stem)) out.push_back(stem);
  std::vector<std::pair<long, std::string>> numbered;
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string& n = deck.name(it);
    if (deck.entry(it).isList() && n.size() > stem.size() && n.size() < stem.size() + 10 &&
        n.compare(0, stem.size(), stem) == 0 && n[stem.size()] != '0' &&
        n.find_first_not_of("0123456789", stem.size()) == std::string::npos)
      numbered.push_back({std::stol(n.substr(stem.size())), n});
  }
  std::sort(numbered.begin(), numbered.end());
  for (const auto& e : numbered) out.push_back(e.second);
  return out;
}

std::vector<std::string> outputLists(const PL& deck) {
  std::vector<std::string> out = numberedLists(deck, "Output");
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string& n = deck.name(it);
    const bool numbered = n.size() > 6 && n.find_first_not_of("0123456789", 6) == std::string::npos;
    if (deck.entry(it).isList() && n.find("Output") != std::string::npos && n != "Output" &&
        !(n.compare(0, 6, "Output") == 0 && numbered))
      out.push_back(n);
  }
  return out;
}

ParamTree treeOf(const PL& l, const std::string& file, const std::string& path) {
  ParamTree t;
  for (auto it = l.begin(); it != l.end(); ++it) {
    const Teuchos::ParameterEntry& e = l.entry(it);
    ParamTree::Entry x;
    x.name = l.name(it);
    using K = ParamTree::Entry::Kind;
    if (e.isList()) {
      x.kind = K::List;
      x.list = std::make_shared<ParamTree>(treeOf(l.sublist(x.name), file, path + "/" + x.name));
    } else if (e.isType<double>()) {
      x.kind = K::Double;
      x.number = Teuchos::getValue<double>(e);
    } else if (e.isType<int>()) {
      x.kind = K::Int;
      x.integer = Teuchos::getValue<int>(e);
    } else if (e.isType<long long>()) {
      x.kind = K::Int;
      x.integer = static_cast<int>(Teuchos::getValue<long long>(e));
    } else if (e.isType<bool>()) {
      x.kind = K::Bool;
      x.flag = Teuchos::getValue<bool>(e);
    } else if (e.isType<std::string>()) {
      x.kind = K::String;
      x.text = Teuchos::getValue<std::string>(e);
    } else {
      fail(file, path, "'" + x.name + "' has a type Periforge cannot pass on (" + e.getAny().typeName() + ")");
    }
    t.entries.push_back(std::move(x));
  }
  return t;
}

double getNumber(const PL& l, const std::string& name) {
  const Teuchos::ParameterEntry& e = l.getEntry(name);
  if (e.isType<double>()) return Teuchos::getValue<double>(e);
  if (e.isType<int>()) return Teuchos::getValue<int>(e);
  if (e.isType<long long>()) return static_cast<double>(Teuchos::getValue<long long>(e));
  throw InputError("'" + name + "' is not a number");
}

double getNumber(const PL& l, const std::string& name, double fallback) {
  return l.isParameter(name) ? getNumber(l, name) : fallback;
}

std::string getText(const PL& l, const std::string& name, const std::string& fallback) {
  return l.isParameter(name) ? scalarAsText(l.getEntry(name)) : fallback;
}

std::string scalarAsText(const Teuchos::ParameterEntry& e) {
  if (e.isType<std::string>()) return Teuchos::getValue<std::string>(e);
  if (e.isType<int>()) return std::to_string(Teuchos::getValue<int>(e));
  if (e.isType<long long>()) return std::to_string(Teuchos::getValue<long long>(e));
  if (e.isType<double>()) {
    std::ostringstream s;
    s.precision(17);
    s << Teuchos::getValue<double>(e);
    return s.str();
  }
  if (e.isType<bool>()) return Teuchos::getValue<bool>(e) ? "true" : "false";
  throw InputError(std::string("unsupported parameter type ") + e.getAny().typeName());
}

std::vector<std::string> commaList(const std::string& text, const std::string& param, const std::string& file,
                                   const std::string& path) {
  std::stringstream ss(text);
  std::string item;
  std::vector<std::string> out;
  while (std::getline(ss, item, ',')) {
    const std::size_t a = item.find_first_not_of(" \t\n"), b = item.find_last_not_of(" \t\n");
    if (a == std::string::npos) fail(file, path, "'" + param + "' has an empty entry");
    out.push_back(item.substr(a, b - a + 1));
  }
  if (out.empty()) fail(file, path, "'" + param + "' is empty");
  return out;
}

}  // namespace pf
