"""Reports: text summaries for the terminal and self-contained HTML."""
