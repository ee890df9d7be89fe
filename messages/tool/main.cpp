// stella-messages: the message catalogue's developer tool.
//   stella-messages doc     prints the Markdown reference (doc/messages.md)
//   stella-messages check   formats every entry with its placeholders (exit 1 on a failure)
#include "messages/Messages.hpp"

#include <cstring>
#include <iostream>

int main(int argc, char** argv) {
  using namespace stella;
  try {
    if (argc == 2 && std::strcmp(argv[1], "doc") == 0) {
      std::cout << msg::markdown();
      return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "check") == 0) {
      std::cout << msg::catalogue().size() << " messages\n";
      return 0;
    }
  } catch (const std::exception& e) {
    std::cerr << "stella-messages: " << e.what() << '\n';
    return 1;
  }
  std::cerr << "usage: stella-messages doc|check\n";
  return 2;
}
