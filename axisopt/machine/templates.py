"""The commented machine templates ``axisopt init machine --kind KIND`` writes; the shipped machines
``problems/machines/<kind>_machine.yaml`` are the same text (a test keeps them so)."""

from types import MappingProxyType

TEMPLATES = MappingProxyType(
    {
        "vmc": """\
# A vertical machining centre: the table (X) on the saddle (Y) on the bed, the spindle head (Z) on a fixed
# column.  Solve it with `axisopt machine solve problems/machines/vmc_machine.yaml`.
name: vmc-machine
description: >
  VMC 800 x 500 x 500: X table on the Y saddle, Z head on the column.  Every part an upper axis chooses adds to
  the mass the axis below carries; the joint search chooses all three axes for the least total cost meeting the
  stiffness at the tool in x, y and z and the lowest natural frequency of the machine.
machine:
  objective: cost
  limits:
    min_tool_stiffness: {x: 40 N/um, y: 40 N/um, z: 40 N/um}
    min_frequency: 60 Hz
  tool_point: {X: 400 mm, Y: 250 mm, Z: 250 mm}
axes:
  Y:
    carried_by: frame
    direction: y
    normal: z                 # the saddle's rails lie on the bed: block normal along z
    # the bed under the saddle's rails (our assumption, a cast bed: not measured)
    frame_stiffness: {x: 1500 N/um, y: 1500 N/um, z: 3000 N/um}
    problem:
      axis:
        stroke: 500 mm
        moving_mass: 350 kg   # the saddle alone: the X axis, table and workpiece are added by the machine
        mounting: fixed-supported
        max_speed: 30 m/min
        axial_load: 3000 N
        acceleration: 3 m/s^2
        cross_load: 2500 N
        normal_load: 2000 N
        tool_height: 450 mm
        cg_height: 150 mm
        table_length: 600 mm
        table_width: 800 mm
        block_spacing: 450 mm
        rail_spacing: 600 mm
      limits:
        max_drag_torque: 2.5 N.m
        min_life: 10000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
  X:
    carried_by: Y
    direction: x
    normal: z
    frame_stiffness: {x: 2000 N/um, y: 2000 N/um, z: 3000 N/um}   # the saddle's top (our assumption)
    carried_at: {height: 200 mm}   # the table's mass acts 200 mm above the saddle's rail plane
    problem:
      axis:
        stroke: 800 mm
        moving_mass: 400 kg   # table with workpiece
        mounting: fixed-supported
        max_speed: 30 m/min
        axial_load: 3000 N
        acceleration: 3 m/s^2
        cross_load: 2500 N
        normal_load: 2000 N
        tool_height: 300 mm
        cg_height: 150 mm
        table_length: 700 mm
        table_width: 500 mm
        block_spacing: 450 mm
        rail_spacing: 400 mm
      limits:
        max_drag_torque: 2.5 N.m
        min_life: 10000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
  Z:
    carried_by: frame
    direction: z
    normal: y                 # the head's rails on the column face
    frame_stiffness: estimate # the column: no figure yet, the stated estimate
    problem:
      axis:
        stroke: 500 mm
        moving_mass: 300 kg
        mounting: fixed-supported
        orientation: vertical
        max_speed: 24 m/min
        axial_load: 3000 N
        acceleration: 3 m/s^2
        table_length: 400 mm
        cross_load: 1500 N
        normal_load: 2000 N
        tool_height: 350 mm
        cg_height: 200 mm
        table_width: 350 mm
        block_spacing: 300 mm
        rail_spacing: 300 mm
      limits:
        max_drag_torque: 2 N.m
        min_life: 10000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G, MELDAS HC (2000 r/min)]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
""",  # noqa: E501
        "moving-column": """\
# A moving-column machine: the column (X) travels on the bed, the headstock (Y) rises on the column, the ram (Z)
# moves out of the headstock; the workpiece stands on a fixed table.  One chain on the frame.
name: moving-column-machine
description: >
  Moving-column machining centre 1600 x 800 x 600: a 600 kg column on X, a 250 kg headstock on Y (vertical),
  a 150 kg ram on Z.  The joint search finds the least total cost that meets the stiffness at the tool and the
  machine's lowest natural frequency.
machine:
  objective: cost
  limits:
    min_tool_stiffness: {x: 30 N/um, y: 30 N/um, z: 30 N/um}
    min_frequency: 40 Hz
axes:
  X:
    carried_by: frame
    direction: x
    normal: z
    frame_stiffness: {x: 1200 N/um, y: 1200 N/um, z: 2500 N/um}   # the bed (our assumption)
    problem:
      axis:
        stroke: 1600 mm
        moving_mass: 600 kg     # the column and its carriage
        mounting: fixed-fixed
        max_speed: 20 m/min
        axial_load: 3000 N
        acceleration: 1.5 m/s^2
        cross_load: 2000 N
        normal_load: 2000 N
        tool_height: 900 mm
        cg_height: 600 mm
        table_length: 900 mm
        table_width: 900 mm
        block_spacing: 700 mm
        rail_spacing: 800 mm
      limits:
        max_drag_torque: 4 N.m
        min_life: 10000 h
      catalog:
        mountings: [fixed-fixed]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G, MELDAS HC (2000 r/min)]
        require: {coupling: [RINGFEDER-GWB-AKN-300]}
  Y:
    carried_by: X
    direction: y
    normal: x                   # the headstock's rails on the column's front face
    frame_stiffness: {x: 800 N/um, y: 1500 N/um, z: 800 N/um}     # the column (our assumption)
    carried_at: {height: 700 mm, offset: 0 mm}   # the headstock and ram act 700 mm up the column
    problem:
      axis:
        stroke: 800 mm
        moving_mass: 250 kg     # the headstock alone: the Z axis and ram are added by the machine
        mounting: fixed-supported
        orientation: vertical
        max_speed: 20 m/min
        axial_load: 3000 N
        acceleration: 1.5 m/s^2
        cross_load: 1500 N
        normal_load: 2000 N
        tool_height: 500 mm
        cg_height: 250 mm
        table_length: 500 mm
        table_width: 400 mm
        block_spacing: 400 mm
        rail_spacing: 350 mm
      limits:
        max_drag_torque: 3 N.m
        min_life: 10000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G, MELDAS HC (2000 r/min)]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
  Z:
    carried_by: Y
    direction: z
    normal: y                   # the ram's rails in the headstock
    frame_stiffness: estimate   # the headstock casting: no figure yet, the stated estimate
    carried_at: {height: 200 mm}
    problem:
      axis:
        stroke: 600 mm
        moving_mass: 150 kg     # the ram with the spindle
        mounting: fixed-supported
        max_speed: 20 m/min
        axial_load: 3000 N
        acceleration: 1.5 m/s^2
        cross_load: 1500 N
        normal_load: 1500 N
        tool_height: 200 mm
        cg_height: 100 mm
        table_length: 700 mm
        table_width: 300 mm
        block_spacing: 500 mm
        rail_spacing: 250 mm
      limits:
        max_drag_torque: 2 N.m
        min_life: 10000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
""",  # noqa: E501
        "gantry": """\
# A gantry: the bridge (Y) on two synchronised screw drives, the cross carriage (X) across the bridge, the ram (Z)
# vertical in the cross carriage with a counterweight.  One chain on the frame; the workpiece on the fixed bed.
name: gantry-machine
description: >
  Gantry 3000 x 1600 x 500: a 700 kg bridge on a twin drive 2.0 m apart, a 250 kg cross carriage on X, a 150 kg
  ram on Z balanced by a 120 kg counterweight that hangs in the cross carriage.  The joint search finds the least
  total cost that meets the stiffness at the tool and the machine's lowest natural frequency.
machine:
  objective: cost
  limits:
    min_tool_stiffness: {x: 25 N/um, y: 25 N/um, z: 25 N/um}
    min_frequency: 30 Hz
axes:
  Y:
    carried_by: frame
    direction: y
    normal: z
    frame_stiffness: {x: 1000 N/um, y: 1000 N/um, z: 2000 N/um}   # the side beds (our assumption)
    problem:
      axis:
        stroke: 3000 mm
        moving_mass: 700 kg       # the bridge; the cross carriage, ram and counterweight are added by the machine
        mounting: fixed-fixed
        max_speed: 15 m/min
        axial_load: 4000 N
        acceleration: 1.5 m/s^2
        table_length: 800 mm
        cross_load: 2000 N
        normal_load: 2000 N
        tool_height: 500 mm
        cg_height: 400 mm
        table_width: 2200 mm
        block_spacing: 550 mm
        rail_spacing: 2100 mm
        twin_drive:
          span: 2000 mm           # screw axis to screw axis
          cross_stroke: 1600 mm   # the X axis's stroke, centred on the bridge
      limits:
        max_drag_torque: 5 N.m
        min_life: 8000 h
        margins:
          critical_speed: 1.2
      catalog:
        mountings: [fixed-fixed]
        vendors: [HIWIN, THK, NSK]
        nut_types: [double]
        require: {motor: [HC202, HC352, HC452], coupling: [RINGFEDER-GWB-AKN-300]}
  X:
    carried_by: Y
    direction: x
    normal: y                     # the cross carriage's rails on the bridge's front face
    frame_stiffness: {x: 600 N/um, y: 500 N/um, z: 600 N/um}       # the bridge beam (our assumption)
    carried_at: {height: 300 mm}
    problem:
      axis:
        stroke: 1600 mm
        moving_mass: 250 kg       # the cross carriage alone: the ram and counterweight are added
        mounting: fixed-supported
        max_speed: 20 m/min
        axial_load: 3000 N
        acceleration: 2 m/s^2
        table_length: 500 mm
        cross_load: 1500 N
        normal_load: 1500 N
        tool_height: 400 mm
        cg_height: 200 mm
        table_width: 400 mm
        block_spacing: 400 mm
        rail_spacing: 350 mm
      limits:
        max_drag_torque: 3 N.m
        min_life: 8000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
  Z:
    carried_by: X
    direction: z
    normal: y                     # the ram's rails on the cross carriage, facing the bridge
    frame_stiffness: estimate     # the cross carriage's casting: the stated estimate
    carried_at: {height: 150 mm}
    problem:
      axis:
        stroke: 500 mm
        moving_mass: 150 kg       # the ram with the spindle
        mounting: fixed-supported
        orientation: vertical
        counterbalance: {kind: counterweight, mass: 120 kg, chain_mass: 5 kg}
        max_speed: 20 m/min
        axial_load: 3000 N
        acceleration: 2 m/s^2
        table_length: 600 mm
        cross_load: 1500 N
        normal_load: 1500 N
        tool_height: 300 mm
        cg_height: 150 mm
        table_width: 300 mm
        block_spacing: 400 mm
        rail_spacing: 250 mm
      limits:
        max_drag_torque: 2 N.m
        min_life: 8000 h
      catalog:
        mountings: [fixed-supported]
        vendors: [HIWIN, NSK]
        nut_types: [double]
        motor_series: [Sigma-7 SGM7G]
        require: {coupling: [RINGFEDER-GWB-AKN-150]}
""",  # noqa: E501
    }
)
# kind -> file name in problems/machines
SHIPPED = MappingProxyType(
    {
        "vmc": "vmc_machine.yaml",
        "moving-column": "moving_column_machine.yaml",
        "gantry": "gantry_machine.yaml",
    }
)
