#!/bin/bash
# The docs stay a reference a newcomer reads in one sitting (issue 48): the
# README at most 8 KB, docs/ under 120 KB in all. A new result goes to the
# commit log or replaces an old figure; it does not pile up.
#   tests/end_to_end/docs_size.sh SOURCE_DIR
set -u
source_dir=$1
readme=$(wc -c < "$source_dir/README.md")
docs=$(cat "$source_dir"/docs/*.md | wc -c)
status=0
if [ "$readme" -gt 8000 ]; then echo "README.md: $readme bytes, more than 8,000"; status=1; fi
if [ "$docs" -ge 120000 ]; then echo "docs/: $docs bytes in all, not under 120,000"; status=1; fi
echo "docs_size: README.md $readme bytes, docs/ $docs bytes"
exit $status
