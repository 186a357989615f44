#pragma once
// Queue words of a deletion phrase (queue_phrases.cpp), used by parse_phrase.
#include <string>
#include <vector>

#include "agents/deletion/deletion.hpp"

namespace chatsim::agents::deletion::detail {

// "the taxi at the front of the queue", "the last car in the line": sets the selector's order
// (queue_head, queue_tail) and blanks the words; false when the phrase says no queue end.
bool queue_end(std::vector<std::string>& p, Selector& s);
// "the drive-thru queue" -> "the queue at the drive thru": the place after the queue, where the
// place readers look for it. Unchanged when no such queue is named.
std::vector<std::string> queue_place_first(const std::vector<std::string>& w);

}  // namespace chatsim::agents::deletion::detail
