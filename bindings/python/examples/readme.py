import plc_timers as plc

ton = plc.TON(pt="T#500ms")  # the IEC on-delay, reference semantics
print(ton.call(1000, in_=True))  # IecOutput(q=False, et=0)
print(ton.call(1500, in_=True))  # IecOutput(q=True, et=500)

# Another runtime's outputs, checked against the reference: the first difference and its rule.
rows = [{"t_ms": 0, "IN": 1, "Q": 0, "ET": 0}, {"t_ms": 500, "IN": 1, "Q": 0, "ET": 500}]
d = plc.check("TON", rows, pt="T#500ms")
assert d is not None  # None: no difference
print(d.line, d.output, d.expected, d.actual, d.rules[0])  # 3 Q True False IEC-EXPIRY-01
