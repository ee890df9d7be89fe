#include "Diagnostics.hpp"

#include <sstream>

namespace stella {

namespace {
Diagnostic make(Severity s, FailureKind k, std::string id, std::string message, SourceLocation at) {
  Diagnostic d;
  d.severity = s;
  d.kind = k;
  d.id = std::move(id);
  d.message = std::move(message);
  d.location = std::move(at);
  return d;
}
} // namespace

Diagnostic Diagnostic::info(std::string id, std::string message, SourceLocation at) {
  return make(Severity::Info, FailureKind::None, std::move(id), std::move(message), std::move(at));
}
Diagnostic Diagnostic::alarm(std::string id, std::string message, SourceLocation at) {
  return make(Severity::Alarm, FailureKind::None, std::move(id), std::move(message), std::move(at));
}
Diagnostic Diagnostic::fatal(std::string id, std::string message, SourceLocation at) {
  return make(Severity::Fatal, FailureKind::Error, std::move(id), std::move(message), std::move(at));
}
Diagnostic Diagnostic::syntax(std::string id, std::string message, SourceLocation at) {
  return make(Severity::Fatal, FailureKind::Syntax, std::move(id), std::move(message), std::move(at));
}
Diagnostic Diagnostic::noConvergence(std::string id, std::string message, SourceLocation at) {
  return make(Severity::Exception, FailureKind::NoConvergence, std::move(id), std::move(message),
              std::move(at));
}

Diagnostic&& Diagnostic::withNote(std::string note) && {
  notes.push_back(std::move(note));
  return std::move(*this);
}
Diagnostic& Diagnostic::withNote(std::string note) & {
  notes.push_back(std::move(note));
  return *this;
}
Diagnostic&& Diagnostic::at(SourceLocation where) && {
  location = std::move(where);
  return std::move(*this);
}

const char* severityTag(Severity s) {
  switch (s) {
  case Severity::Info:
    return "<I>";
  case Severity::Alarm:
    return "<A>";
  case Severity::Fatal:
    return "<F>";
  case Severity::Exception:
    return "<S>";
  }
  return "<F>";
}

namespace {
const char* severityWord(Severity s) {
  switch (s) {
  case Severity::Info:
    return "info";
  case Severity::Alarm:
    return "warning";
  case Severity::Fatal:
  case Severity::Exception:
    return "error";
  }
  return "error";
}
} // namespace

std::string formatDiagnostic(const Diagnostic& d) {
  std::ostringstream out;
  if (d.location.file) {
    out << d.location.str() << ": ";
  }
  out << severityWord(d.severity) << ": " << d.message;
  if (!d.id.empty()) {
    out << " [" << d.id << "]";
  }
  out << '\n';
  if (d.location.known()) {
    std::string_view text = d.location.file->line(d.location.line);
    if (!text.empty()) {
      out << "    " << text << '\n' << "    ";
      int col = d.location.column < 1 ? 1 : d.location.column;
      for (int i = 1; i < col && static_cast<std::size_t>(i - 1) < text.size(); ++i) {
        out << (text[static_cast<std::size_t>(i - 1)] == '\t' ? '\t' : ' ');
      }
      int len = d.location.length < 1 ? 1 : d.location.length;
      out << '^';
      for (int i = 1; i < len; ++i) {
        out << '~';
      }
      out << '\n';
    }
  }
  for (const auto& note : d.notes) {
    out << "note: " << note << '\n';
  }
  return out.str();
}

InternalError::InternalError(std::string message, const char* file, int line) {
  std::ostringstream out;
  out << "internal error at " << file << ':' << line << ": " << message;
  text_ = out.str();
}

} // namespace stella
