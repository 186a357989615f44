#pragma once
// The makes and models of agents/prompts/vehicles.json, and the word matching lexicon.cpp and
// makes.cpp share. Internal to agents/language.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace chatsim::agents::lexicon::detail {

// A make and its models as vehicles.json lists them, each name already split into words.
struct Make {
  std::string brand, type;
  std::vector<std::vector<std::string>> names;
  std::vector<std::pair<std::vector<std::string>, std::string>> models;  // longest first
  std::vector<std::vector<std::string>> ambiguous;  // names that are also ordinary words ("seat", not "cupra")
};

std::filesystem::path vocabulary_file();  // vehicles.json; the other vocabulary files sit beside it
const std::vector<Make>& makes();
bool words_at(const std::vector<std::string>& w, size_t at, const std::vector<std::string>& phrase);
// As words_at, or with the phrase's last word in the plural ("range rovers", "model ys").
bool words_at_plural(const std::vector<std::string>& w, size_t at, const std::vector<std::string>& phrase);
bool is_unit_word(const std::string& w);
// Where a vehicle noun belongs: after a determiner ("a", "the", "another") and words that only
// describe it ("new", "big", "dark", "second"); colours and numbers are asked for on their own.
bool is_vehicle_determiner(const std::string& w);
bool is_vehicle_premodifier(const std::string& w);

}  // namespace chatsim::agents::lexicon::detail
