// script_run.hh: the read-echo-run loop and axis-word helper shared by the script-driven unit drivers.
#ifndef OPENEMC_TESTS_SCRIPT_RUN_HH
#define OPENEMC_TESTS_SCRIPT_RUN_HH

#include <iostream>
#include <string>

#include "emc/rs274ngc/interp_state.hh"
#include "script_block.hh"

// Copy the X Y Z A B C words of a block into pose; axes without a word keep their value.
inline void take_axis_words(const Block &b, Pose &pose)
{
    const char letters[] = "xyzabc";
    for (int i = 0; i < 6; i++)
        if (b.word(letters[i]))
            pose[i] = b.value(letters[i]);
}

// Run the script on in: every non-blank line is echoed as "> line", '#' lines only echoed,
// others passed to run_line; an InterpError prints "ERROR: text" and then calls on_error.
template <typename RunLine, typename OnError>
inline int run_script(std::istream &in, RunLine run_line, OnError on_error)
{
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty())
            continue;
        std::cout << "> " << line << std::endl;
        if (line[0] == '#')
            continue;
        try {
            run_line(line);
        } catch (const InterpError &e) {
            std::cout << "ERROR: " << e.what() << std::endl;
            on_error();
        }
        std::cout.flush();
    }
    return 0;
}

#endif
