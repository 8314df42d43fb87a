#pragma once
// Test data shared by the ISO 23725 codec tests: the research note's catalogue examples, one JSON frame a line.
#include <fstream>
#include <string>
#include <vector>

inline std::vector<std::string> loadCatalogueExamples() {
    std::ifstream in(OCU_ISO_TEST_DATA "/catalogue_examples.jsonl");
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);)
        if (!l.empty())
            lines.push_back(l);
    return lines;
}
