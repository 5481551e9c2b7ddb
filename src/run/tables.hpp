// cambrian: the run's tab-separated tables (individuals.tsv, generations.tsv), written from the
// same records the history keeps; every measure of the task gets a column by name.
#pragma once

#include "cambrian/outcome.hpp"

#include "evolution/generation_record.hpp"
#include "evolution/population.hpp"

#include <string>
#include <vector>

namespace cambrian {

/// Header line of individuals.tsv (tab separated, ends with a newline): the fixed columns, then
/// one per measure.
std::string individualsTsvHeader(const std::vector<MeasureInfo>& measures);
/// One line of individuals.tsv; parents are joined with ',' ('-' when none); fitness and
/// measures in %.17g ("nan" for a measure the outcome lacks).
std::string individualsTsvRow(const Individual& individual,
                              const std::vector<MeasureInfo>& measures);
/// Header line of generations.tsv.
std::string generationsTsvHeader();
/// One line of generations.tsv.
std::string generationsTsvRow(const GenerationRecord& record);

/// Writes `text` to `path` atomically (temporary file, rename); throws Error(output_file)
/// naming the path.
void writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace cambrian
