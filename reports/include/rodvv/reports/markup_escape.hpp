#pragma once
// Escaping of free text (case titles, physics descriptions, failure messages) for the markup
// formats, so that a title like `<b>&"'` is shown literally and cannot break the document.
#include <string>
#include <string_view>

namespace rodvv::reports {

// HTML/XML text and attribute values: & < > " ' become entities. Characters XML 1.0 forbids
// (C0 controls other than tab, LF, CR) become U+FFFD; in attributes, tab/LF/CR become numeric
// references so they survive attribute-value normalisation.
std::string escape_xml(std::string_view text);
std::string escape_xml_attribute(std::string_view text);

// Markdown inline text: backslash-escapes the characters that start markup (\ ` * _ [ ] < > | &
// ~ #), and turns line breaks into spaces so a table cell stays on one row.
std::string escape_markdown(std::string_view text);

// A file-name and anchor safe form: every character other than [A-Za-z0-9] becomes '-'
// (the same rule as plot_results.py).
std::string slugify(std::string_view text);

}  // namespace rodvv::reports
