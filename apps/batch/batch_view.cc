#include "apps/batch/batch_view.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "apps/batch/batch_job.h"
#include "datasets/io/atomic_file.h"
#include "view/page_html.h"
#include "view/view_inputs.h"

namespace implicitfit {
namespace {

namespace fs = std::filesystem;

std::string Figure(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string Link(const std::string& file, const std::string& text) {
  return "<a href=\"" + HtmlEscape(file) + "\">" + HtmlEscape(text) + "</a>";
}

std::string ResultSuffix(const BatchOptions& o) { return o.scene ? ".scene.json" : ".model.json"; }

// The page of one input; "" when written, else why not.
std::string WriteInputPage(const BatchInput& in, const BatchOptions& o) {
  ViewInputOptions options;
  options.quiet = true;
  if (o.scene) options.labels = BatchOutputPath(o, in, ".labels.txt");
  try {
    ViewPage page = ReadViewInputs({in.path, BatchOutputPath(o, in, ResultSuffix(o).c_str())}, options);
    page.title = "batch " + in.name + " (" + in.path + ")";
    WritePage(page, BatchOutputPath(o, in, ".view.html"));
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string IndexHtml(const std::vector<BatchInput>& inputs,
                      const std::vector<BatchOutcome>& outcomes, const BatchOptions& o,
                      const std::vector<std::string>& page_errors) {
  std::string rows;
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const BatchOutcome& r = outcomes[i];
    const BatchInput& in = inputs[i];
    const bool page = r.Succeeded() && page_errors[i].empty();
    const std::string status = BatchStatusName(r.status);
    rows += "<tr class=\"" + status + "\"><td>" +
            (page ? Link(in.name + ".view.html", in.name) : HtmlEscape(in.name)) + "</td><td>" +
            status + "</td>";
    if (r.HasFigures())
      rows += "<td class=\"num\">" + std::to_string(r.points) + "</td><td class=\"num\">" +
              std::to_string(r.inliers) + "</td><td class=\"num\">" + Figure("%.4g", r.rms) +
              "</td>";
    else
      rows += "<td></td><td></td><td></td>";
    rows += "<td class=\"num\">" + Figure("%.2f", r.seconds) + "</td><td>";
    if (r.Succeeded()) rows += Link(in.name + ResultSuffix(o), "result") + " ";
    if (r.status != BatchStatus::kError) rows += Link(in.name + ".report.json", "report");
    rows += "</td><td>" + HtmlEscape(r.Succeeded() ? (page_errors[i].empty() ? "" : "page: " + page_errors[i])
                                                   : r.Failure()) +
            "</td></tr>\n";
  }
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>implicitfit "
         "batch</title>\n<style>body{font:13px system-ui,sans-serif;margin:16px}"
         "table{border-collapse:collapse}td,th{padding:2px 8px;border-bottom:1px solid #ddd;"
         "text-align:left}td.num{text-align:right;font-variant-numeric:tabular-nums}"
         "tr.failed td,tr.error td{color:#a02020}</style></head><body>\n"
         "<h1>implicitfit batch</h1>\n<p>" +
         std::to_string(outcomes.size()) +
         " inputs. Each name links its page (docs/view.md); RMS as in summary.csv.</p>\n"
         "<table><tr><th>input</th><th>status</th><th>points</th><th>inliers</th><th>RMS</th>"
         "<th>seconds</th><th>files</th><th>error</th></tr>\n" +
         rows + "</table></body></html>\n";
}

}  // namespace

size_t WriteBatchViews(const std::vector<BatchInput>& inputs,
                       const std::vector<BatchOutcome>& outcomes, const BatchOptions& options,
                       const std::string& index_name, bool quiet) {
  std::vector<std::string> page_errors(outcomes.size());
  size_t written = 0;
  for (size_t i = 0; i < outcomes.size() && i < inputs.size(); ++i) {
    if (!outcomes[i].Succeeded()) continue;
    if (!quiet) std::cerr << "batch: page " << (i + 1) << "/" << outcomes.size() << " " << inputs[i].name << "\n";
    page_errors[i] = WriteInputPage(inputs[i], options);
    written += page_errors[i].empty();
  }
  const std::string index = (fs::path(options.out_dir) / index_name).string();
  WriteFileAtomically(index, IndexHtml(inputs, outcomes, options, page_errors));
  std::printf("index: %s (%zu pages)\n", index.c_str(), written);
  return written;
}

}  // namespace implicitfit
