#!/bin/bash
# The README stays a page a newcomer reads in one sitting: at most 8 KB
# (issue 72). docs/ is a reference of the system as it is, without a cap.
#   tests/end_to_end/docs_size.sh SOURCE_DIR
set -u
source_dir=$1
readme=$(wc -c < "$source_dir/README.md")
docs=$(cat "$source_dir"/docs/*.md | wc -c)
status=0
if [ "$readme" -gt 8000 ]; then echo "README.md: $readme bytes, more than 8,000"; status=1; fi
echo "docs_size: README.md $readme bytes, docs/ $docs bytes"
exit $status
