"""The dyad kinds, as discovery finds them (polygons.dyads.discovered): written by
``python -m polygons.dyads``; do not edit (tests/test_cold_start.py holds it equal
to discovery)."""

#: role -> kind modules, in the order the planner asks them
ORDER = {
    'driver': ('crank', 'slider_drive'),
    'slot': ('rpr', 'slide'),
    'point': ('wheel_pin', 'rpp', 'image', 'rrp', 'guided', 'crossing', 'slot_slider', 'rrr'),
    'group': ('triad', 'triad_slider'),
}
#: kind module -> its group class
CLASSES = {
    'crank': 'CrankDyad',
    'slider_drive': 'SliderDriveDyad',
    'rpr': 'RPR',
    'slide': 'SlideDyad',
    'wheel_pin': 'WheelPin',
    'rpp': 'RPP',
    'image': 'Image',
    'rrp': 'RRP',
    'guided': 'Guided',
    'crossing': 'Crossing',
    'slot_slider': 'SlotSlider',
    'rrr': 'RRR',
    'triad': 'Triad',
    'triad_slider': 'TriadSlider',
}
