"""The tube-in-tubesheet mesh at the seed's size (Code_Aster 2012: HEXA27, 130 000 dofs, 10 000 of
them in contact): `--set`s on scenes/tube-expansion-3d.yaml's generator giving 129 294 dofs and
4 251 mortar multipliers in hex27 (doc/performance.md, "At the seed's size"). Shared by the bench
scripts that run the tube at that size."""

SEED_MESH = ["Mesh/tube-in-tubesheet/Tube Radial Divisions=4",
             "Mesh/tube-in-tubesheet/Sheet Radial Divisions=10",
             "Mesh/tube-in-tubesheet/Circumferential Divisions=6",
             "Mesh/tube-in-tubesheet/Axial Divisions=[5,44,5]",
             "Mesh/tube-in-tubesheet/Sheet Circumferential Divisions=8",
             "Mesh/tube-in-tubesheet/Sheet Axial Divisions=42"]
