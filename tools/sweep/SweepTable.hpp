#pragma once
// The table of a sweep: one row per point of the grid, written as CSV (read back by
// `stella sweep --report`) and Markdown, with its Pareto front of error against time.

#include <filesystem>
#include <string>
#include <vector>

namespace stella::sweep {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  int column(const std::string& name) const; // -1 when absent
  std::string at(std::size_t row, const std::string& name) const;
  void set(std::size_t row, const std::string& name, const std::string& value);
};

// The indices of the points no other point beats on both time and error (smaller or equal on
// both, smaller on one); `eligible` false excludes a point (a failed run). Sorted by time.
std::vector<std::size_t> paretoFront(const std::vector<double>& time, const std::vector<double>& error,
                                     const std::vector<bool>& eligible);

// Fills the column `pareto` ("yes" or "") from `time_s` (or `wall_s`), `error` and `finished`;
// returns the front.
std::vector<std::size_t> markParetoFront(Table& table);

std::string toCsv(const Table& table);
Table fromCsv(const std::string& text); // throws SweepError on a malformed file

// The Markdown page: the table, then the Pareto front in words.
std::string toMarkdown(const Table& table, const std::vector<std::size_t>& front);

std::string formatNumber(double value, int digits);

} // namespace stella::sweep
