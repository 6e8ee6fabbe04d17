"""Spec texts shared by several test modules.

DRUM is Hibbeler 12e Example 17.11 (textbook answers alpha = 11.3 rad/s^2,
T = 106 N, a = 4.52 m/s^2).
"""

DRUM = """\
problem: Drum and hanging block
source: Hibbeler 12e Example 17.11
units: SI

given:
  m_d = 60 kg       # drum mass
  k_O = 0.25 m      # radius of gyration about O
  r   = 0.4 m       # drum radius
  m_b = 20 kg       # block mass

equations:
  I_O = m_d*k_O^2          # radius of gyration: I_O = m k_O²
  T*r = I_O*alpha          # ΣM_O = I_O α (drum), CCW positive
  m_b*g - T = m_b*a        # ΣF_y = m a_y (block), downward positive
  a = alpha*r              # cord does not slip: a = α r

find: alpha, T [N], a [m/s^2]

answers:
  alpha = 11.3 rad/s^2 +- 0.5%
  T     = 106 N        +- 0.5%
  a     = 4.52 m/s^2   +- 0.5%
"""
