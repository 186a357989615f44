#pragma once
// The asset agent: which 3D asset an instruction asks for (type, brand, colour), chosen from
// the asset catalogue; unknown brands fall back to the nearest generic type, said so.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace chatsim::agents::asset {

// What the instruction says (the "LLM" part): only the fields it mentions.
struct AssetRequest {
  std::optional<std::string> type;     // car, suv, truck, ...
  std::optional<std::string> brand;    // porsche
  std::optional<std::string> brand_name;  // the make as said when another of its names ("vauxhall" for opel)
  std::optional<std::string> unknown_brand;  // a capitalised word we do not know ("Zorbex")
  std::optional<std::string> color;    // as said: "dark blue"
  std::optional<std::array<int, 3>> color_rgb;
  std::optional<int> count;
};
AssetRequest parse_asset(const std::string& instruction);
nlohmann::json to_json(const AssetRequest& r);
AssetRequest asset_request_from_json(const nlohmann::json& j);

// The chosen asset, as it goes into the edit state.
struct AssetChoice {
  std::string asset;                   // porsche_911, police_car, sedan, ...
  std::string type;
  std::string category;
  std::vector<std::string> brand_words;
  std::array<double, 3> size_lwh{};
  std::array<int, 3> color_rgb{};
  std::optional<std::string> note;     // e.g. unknown brand
};

// base: the vehicle being revised (keeps what the request does not change).
AssetChoice choose_asset(const AssetRequest& request, const std::optional<AssetChoice>& base = std::nullopt);
nlohmann::json to_json(const AssetChoice& c);
AssetChoice asset_choice_from_json(const nlohmann::json& j);

}  // namespace chatsim::agents::asset
