"""What an algorithm traces over: the scalar tree, the limbs in SIMD lanes, the coupled robot's tree."""
