"""Decision-making clients of the Signal Contract and the testbeds they run on.

Clients never read text: they hand reports and location signatures to
:class:`lucifer.clients.middleware.Middleware` and consume only the signals it returns.
"""
