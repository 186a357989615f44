#include "agents/asset/asset_choice.hpp"

#include <algorithm>
#include <cctype>

#include "agents/asset/catalog.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "common/util/json_fields.hpp"

namespace chatsim::agents::asset {
namespace {

// "faster than the traffic", "through the cars": a noun a preposition governs is where or what
// the added vehicle is compared with, not what is added.
bool governed_by_preposition(const std::vector<std::string>& w, size_t begin) {
  static const char* determiners[] = {"the", "a", "an", "other", "all", "some", "this", "that", "those", "these", "my",
                                      "our", "any", "slow", "slower", "parked", "moving", "recorded", "existing"};
  static const char* prepositions[] = {"than", "with", "through", "past", "around", "amid", "amongst", "from", "against",
                                       "into", "onto", "among", "between", "toward", "towards", "behind", "beside"};
  size_t i = begin;
  while (i > 0 && (std::find_if(std::begin(determiners), std::end(determiners),
                                [&](const char* d) { return w[i - 1] == d; }) != std::end(determiners) ||
                   lexicon::is_color_word(w[i - 1])))
    --i;
  return i > 0 && std::find_if(std::begin(prepositions), std::end(prepositions),
                               [&](const char* p) { return w[i - 1] == p; }) != std::end(prepositions);
}

}  // namespace

AssetRequest parse_asset(const std::string& instruction) {
  auto w = text::words(instruction);
  // What follows a relation names another vehicle ("a police car chasing the porsche", "an SUV
  // tailgating the orange car").
  size_t rel = text::find_any(w, {"toward the", "near the", "where the", "instead of the", "in place of the",
                                  "between the", "between two", "among the", "overtake the", "overtakes the",
                                  "overtaking the", "pass the", "passing the", "like the", "same as the",
                                  "same color as", "same shade as", "same size as", "same type as", "as fast as",
                                  "as quick as", "as quickly as", "as slow as", "as slowly as", "speed of", "speed as"});
  for (const auto& r : lexicon::relation_phrases())
    for (size_t at = text::find_words(w, r.words); at != std::string::npos; at = text::find_words(w, r.words, at + 1)) {
      const size_t next = at + r.words.size();
      if (next < w.size() && (w[next] == "the" || w[next] == "it" || w[next] == "that" || w[next] == "this")) {
        rel = std::min(rel, at);
        break;
      }
    }
  if (rel != std::string::npos && rel > 0) w.resize(rel);
  AssetRequest r;
  auto types = lexicon::find_types(w);
  // Unless nothing else names what is added: "block the lanes with barriers", "turn it into a van".
  auto ungoverned = types;
  std::erase_if(ungoverned, [&](const lexicon::TypeMention& t) { return governed_by_preposition(w, t.begin); });
  // "drive off into the traffic": traffic a preposition governs is never what it turns into.
  std::erase_if(types, [&](const lexicon::TypeMention& t) {
    return w[t.begin] == "traffic" && governed_by_preposition(w, t.begin);
  });
  if (!ungoverned.empty() || !lexicon::find_brands(w).empty()) types = ungoverned;
  for (size_t k = 0; k < types.size(); ++k) {
    const auto& t = types[k];
    if (!t.type.addable()) continue;
    r.type = t.type.type;
    // "a police motorbike": of two nouns in a row the last is the head ("police" only qualifies it).
    if (k + 1 < types.size() && types[k + 1].begin == t.end && types[k + 1].type.type != "object")
      r.type = types[k + 1].type.type;
    break;
  }
  const auto brands = lexicon::find_brands(w);
  if (!brands.empty()) {
    r.brand = brands.front().brand;
    if (!brands.front().name.empty()) r.brand_name = brands.front().name;
    if (!r.type || *r.type == "car") {
      if (brands.front().type != "car" || !r.type) r.type = brands.front().type;
    }
  } else if (const auto name = lexicon::unknown_vehicle_name(w, 1);
             name && (types.empty() || name->second <= types.front().begin)) {
    // "a black Zorblax", "a Zorblax van": a make nobody knows, said in the choice's note as written.
    r.unknown_brand = text::join(w, name->first, name->second);
    std::string lower = instruction;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    if (const size_t at = lower.find(*r.unknown_brand); at != std::string::npos)
      r.unknown_brand = instruction.substr(at, r.unknown_brand->size());
  }
  const auto colors = lexicon::find_colors(w);
  if (!colors.empty()) {
    r.color = colors.front().name;
    r.color_rgb = colors.front().rgb;
  }
  if (types.empty() && !brands.empty()) {
    // "two range rovers", "a pair of teslas": the count word before the make, else "some".
    if (brands.front().plural) r.count = 3;
    for (size_t i = brands.front().begin; i-- > 0 && brands.front().begin - i <= 3;) {
      size_t used = 0;
      const auto v = text::number_at(w, i, &used);
      if (v && i + used <= brands.front().begin && *v >= 2 && std::floor(*v) == *v) {  // "a bmw" is one
        r.count = int(*v);
        break;
      }
    }
  }
  if (!types.empty()) {
    // "some cones", "cars": more than one, how many unsaid.
    if (types.front().plural && !text::has_any(w, {"all", "every", "each"})) r.count = 3;
    // "a row of parked cars", "a line of vans": several, not the "a" of the row.
    const bool group = text::has_any(w, {"row of", "rows of", "line of", "string of", "column of", "convoy of",
                                         "bunch of", "lot of", "lots of", "number of", "fleet of", "queue of"});
    if (group && types.front().plural) {
      r.count = 4;
      return r;
    }
    const size_t at = types.front().begin;
    // "two traffic cones", "500 cars", "a couple of vans": the count word right before the noun phrase.
    for (size_t i = at; i-- > 0 && at - i <= 4;) {
      // "a peugeot 308 estate": the model's number is no count.
      if (!brands.empty() && i >= brands.front().begin && i < brands.front().end) continue;
      size_t used = 0;
      const auto v = text::number_at(w, i, &used);
      // "forward by 20 ... van": an amount after "by", "at" or "to" counts metres, not vans.
      const bool amount = i > 0 && (w[i - 1] == "by" || w[i - 1] == "at" || w[i - 1] == "to");
      if (v && !amount && i + used <= at && *v >= 1 && std::floor(*v) == *v) {
        r.count = int(*v);
        break;
      }
    }
  }
  return r;
}

nlohmann::json to_json(const AssetRequest& r) {
  nlohmann::json j = nlohmann::json::object();
  util::put_optional(j, "type", r.type);
  util::put_optional(j, "brand", r.brand);
  util::put_optional(j, "brand_name", r.brand_name);
  util::put_optional(j, "unknown_brand", r.unknown_brand);
  util::put_optional(j, "color", r.color);
  util::put_optional(j, "color_rgb", r.color_rgb);
  util::put_optional(j, "count", r.count);
  return j;
}

AssetRequest asset_request_from_json(const nlohmann::json& j) {
  AssetRequest r;
  if (!j.is_object()) return r;
  util::get_optional(j, "type", r.type);
  util::get_optional(j, "brand", r.brand);
  util::get_optional(j, "brand_name", r.brand_name);
  util::get_optional(j, "unknown_brand", r.unknown_brand);
  util::get_optional(j, "color", r.color);
  util::get_optional(j, "color_rgb", r.color_rgb);
  util::get_optional(j, "count", r.count);
  return r;
}

AssetChoice choose_asset(const AssetRequest& r, const std::optional<AssetChoice>& base) {
  AssetChoice out = base.value_or(AssetChoice{});
  const bool new_vehicle = !base.has_value();
  const std::string type = r.type.value_or(base ? base->type : "car");
  const Catalog& catalog = Catalog::instance();
  const CatalogEntry* entry = nullptr;
  if (r.brand) {
    for (const auto& e : catalog.entries())
      if (r.brand == e.brand && (!r.type || e.type == type)) entry = &e;
    if (entry == nullptr) {  // a brand we know, but not in this type: generic mesh with the brand's name
      const auto& g = catalog.generic(type);
      out.asset = *r.brand + "_" + g.asset;
      out.brand_words = {*r.brand};
      out.size_lwh = g.size_lwh;
      if (new_vehicle) out.color_rgb = g.color_rgb;
    }
  } else if (r.type && (new_vehicle || *r.type != base->type)) {
    entry = &catalog.generic(type);
  } else if (new_vehicle) {
    entry = &catalog.generic(type);
  }
  if (entry != nullptr) {
    out.asset = entry->asset;
    out.brand_words.clear();
    if (!entry->brand.empty()) out.brand_words.push_back(entry->brand);
    out.size_lwh = entry->size_lwh;
    if (new_vehicle) out.color_rgb = entry->color_rgb;
  }
  // "landrover" is labelled "land rover" too: the name people write.
  if (!out.brand_words.empty()) {
    const std::string display = lexicon::make_display_name(out.brand_words.front());
    if (std::find(out.brand_words.begin(), out.brand_words.end(), display) == out.brand_words.end())
      out.brand_words.push_back(display);
  }
  // "a Vauxhall Corsa" is an Opel mesh, labelled with the name the user gave too.
  if (r.brand_name && std::find(out.brand_words.begin(), out.brand_words.end(), *r.brand_name) == out.brand_words.end())
    out.brand_words.push_back(*r.brand_name);
  out.type = type;
  if (const auto* vt = lexicon::vehicle_type(type)) out.category = vt->category;
  if (r.color_rgb) out.color_rgb = *r.color_rgb;
  if (type == "construction" || type == "trailer")
    out.note = "no " + type + " model in the asset library; a generic truck stands in (labelled " + out.category + ")";
  if (r.unknown_brand && !r.brand) {
    out.note = "no asset for the brand '" + *r.unknown_brand + "'; used a generic " + type;
    out.brand_words = {*r.unknown_brand};
  }
  return out;
}

nlohmann::json to_json(const AssetChoice& c) {
  nlohmann::json j{{"asset", c.asset}, {"type", c.type}, {"category", c.category}, {"brand_words", c.brand_words},
                   {"size_lwh", c.size_lwh}, {"color_rgb", c.color_rgb}};
  util::put_optional(j, "note", c.note);
  return j;
}

AssetChoice asset_choice_from_json(const nlohmann::json& j) {
  AssetChoice c;
  c.asset = j.value("asset", "");
  c.type = j.value("type", "car");
  c.category = j.value("category", "vehicle.car");
  c.brand_words = j.value("brand_words", std::vector<std::string>{});
  c.size_lwh = j.value("size_lwh", std::array<double, 3>{4.5, 1.9, 1.5});
  c.color_rgb = j.value("color_rgb", std::array<int, 3>{128, 128, 128});
  util::get_optional(j, "note", c.note);
  return c;
}

}  // namespace chatsim::agents::asset
