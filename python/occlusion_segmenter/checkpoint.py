"""The checkpoint: one torch.save'd dict, checked when loaded."""

import torch

from . import CLASSES
from .model import PointNetSeg

FORMAT = "occlusion-segmenter/1"


def save(path, model, settings, history):
    import os
    temporary = path + ".partial"
    torch.save({"format": FORMAT, "classes": list(CLASSES),
                "settings": settings, "history": history,
                "state_dict": model.state_dict()}, temporary)
    os.replace(temporary, path)


def load(path):
    """(model in eval mode, the saved dict)."""
    saved = torch.load(path, map_location="cpu")
    if not isinstance(saved, dict) or saved.get("format") != FORMAT:
        raise ValueError(f"{path}: not an {FORMAT} checkpoint "
                         "(made by python3 -m occlusion_segmenter train)")
    if saved["classes"] != list(CLASSES):
        raise ValueError(f"{path}: its classes {saved['classes']} are not "
                         "the 13 S3DIS classes in order")
    settings = saved["settings"]
    model = PointNetSeg(settings["in_channels"], len(CLASSES),
                        settings["width"])
    model.load_state_dict(saved["state_dict"])
    model.eval()
    return model, saved
