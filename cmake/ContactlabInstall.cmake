# Install rules filled in by the install/package-config work.
