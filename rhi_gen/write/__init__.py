"""Write: a rendered plan against the disk, and the records that make regeneration safe.

changes.py (created / changed / unchanged / removed), transaction.py (apply all-or-nothing),
merge.py (carry user regions over, refuse to overwrite hand edits), regions.py (user-region
syntax), manifest.py (generated/.rhi-gen-manifest: fingerprints, file hashes, generator version),
semantic_diff.py (a pending regeneration in robot terms), backups.py (--force), diff_text.py.
"""
