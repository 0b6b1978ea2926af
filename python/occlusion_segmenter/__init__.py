"""A small learned reference segmenter for the occlusion study.

A PointNet-style network (per-point MLP, block max-pool, per-point head) in
PyTorch, trained on rooms made by generate_s3dis_room --dataset, and run by
the study as a persistent worker (segmenter_mode worker) so that torch is
imported and the model loaded once per study. docs/study.md shows the
commands.
"""

# The 13 S3DIS classes, in the dataset's order; a checkpoint's outputs.
CLASSES = ("ceiling", "floor", "wall", "beam", "column", "window", "door",
           "table", "chair", "sofa", "bookcase", "board", "clutter")

# The study's default class mapping (the seed's table 3.1), name -> id.
SEED_TABLE = {"wall": 0, "floor": 1, "ceiling": 1, "chair": 4, "sofa": 5,
              "table": 6, "door": 7, "window": 8, "bookcase": 9,
              "beam": 20, "board": 21, "clutter": 25, "column": 26}
