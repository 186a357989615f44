// chatsim-foreground: the foreground agent on the bus. Its logic lives in agents/; this only wires it.
#include "processes/agent_process.hpp"

int main(int argc, char** argv) { return chatsim::processes::agent_main(argc, argv, "foreground"); }
