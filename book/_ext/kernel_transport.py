"""The chapters' kernels talk to the book's build over an encrypted channel.

ipykernel (7.4 in the course's pins) warns, once per chapter, "Kernel is running over
TCP without encryption" when its manager gives it no CurveZMQ keys. jupyter_client (8.10
here) provisions them when ``KernelManager.transport_encryption`` is 'auto' and the
kernel's kernelspec declares ``supported_encryption: ["curve"]`` (ipykernel's does); its
default is 'disabled'. A Jupyter server reads that setting from its configuration, but
myst-nb builds its kernel managers without one, so this extension sets the default of
the trait in the build's process: the chapters then run encrypted and the warning has
nothing to warn about. With an older jupyter_client, or a pyzmq without CurveZMQ, it
does nothing (and an older ipykernel does not warn).
"""


def setup(app):
    import zmq
    from jupyter_client.manager import KernelManager

    trait = getattr(KernelManager, "transport_encryption", None)
    if trait is not None and zmq.has("curve"):
        trait.default_value = "auto"
    return {"parallel_read_safe": True, "parallel_write_safe": True}
