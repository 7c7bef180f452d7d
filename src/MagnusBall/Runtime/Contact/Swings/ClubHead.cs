using System;

namespace MagnusBall.Contact.Swings
{
    /// <summary>
    /// A golf club head as a free rigid body at impact: its mass, where its centre of gravity (CG) sits behind the
    /// impact point, and its moments of inertia about the CG. A head with no CG depth and no impact height, or with
    /// infinite moments, is a point mass (the model of <see cref="ClubSwing"/>'s first constructor).
    /// </summary>
    /// <remarks>
    /// <para>Geometry, in the face's own frame at impact: the CG lies <see cref="CenterOfGravityDepth"/> behind the
    /// impact point along the face normal and <see cref="ImpactHeight"/> below it along the face (the impact is that far
    /// above the CG's projection on the face, the foot of the perpendicular from the CG). The principal axes of inertia
    /// are taken along the face's heel-toe axis, the axis up the face (near vertical for a driver) and the face normal
    /// (an assumption: products of inertia are dropped).</para>
    /// <para>The head rotates about its CG during the impact: the normal force has the lever <see cref="ImpactHeight"/>
    /// about the heel-toe axis (golf's vertical gear effect), friction along the face the lever
    /// <see cref="CenterOfGravityDepth"/> (about the heel-toe axis for friction up the face, about the vertical axis for
    /// friction across it when face and path differ). An impact toward the heel or the toe is not a parameter, so the
    /// horizontal gear effect of a heel or toe hit (the normal force's lever about the vertical axis) is not modelled.
    /// docs/impacts.md gives the sources and what the rotation does to a driver's spin.</para>
    /// </remarks>
    public readonly struct ClubHead
    {
        /// <summary>Creates a head.</summary>
        /// <param name="mass">The head's mass, kg; finite and &gt;= 1e-6 (a milligram).</param>
        /// <param name="centerOfGravityDepth">The CG's distance behind the impact point along the face normal, m; in [0, 0.2].</param>
        /// <param name="impactHeight">The impact point's distance up the face above the CG's projection on the face, m; in [-0.05, 0.05].</param>
        /// <param name="heelToeInertia">The moment of inertia about the heel-toe axis through the CG, kg m^2; &gt;= 1e-9 (0.01 g cm^2), or positive infinity.</param>
        /// <param name="verticalInertia">About the axis up the face through the CG, kg m^2; &gt;= 1e-9, or positive infinity.</param>
        /// <param name="faceNormalInertia">About the face-normal axis through the CG, kg m^2; &gt;= 1e-9, or positive infinity.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public ClubHead(
            double mass, double centerOfGravityDepth = 0, double impactHeight = 0, double heelToeInertia = double.PositiveInfinity,
            double verticalInertia = double.PositiveInfinity, double faceNormalInertia = double.PositiveInfinity)
        {
            Mass = SwingGeometry.RequireBodyMass(mass, nameof(mass));
            CenterOfGravityDepth = Require.InRange(centerOfGravityDepth, 0, 0.2, nameof(centerOfGravityDepth));
            ImpactHeight = Require.InRange(impactHeight, -0.05, 0.05, nameof(impactHeight));
            HeelToeInertia = RequireMoment(heelToeInertia, nameof(heelToeInertia));
            VerticalInertia = RequireMoment(verticalInertia, nameof(verticalInertia));
            FaceNormalInertia = RequireMoment(faceNormalInertia, nameof(faceNormalInertia));
        }

        /// <summary>The smallest head mass, kg (a milligram).</summary>
        internal const double MinimumMass = SwingGeometry.MinimumBodyMass;

        /// <summary>The smallest moment of inertia, kg m^2 (0.01 g cm^2).</summary>
        internal const double MinimumMoment = 1e-9;

        /// <summary>A point mass of any positive mass (already checked by the caller): ClubSwing's first constructor.</summary>
        internal ClubHead(double checkedMass, bool pointMass)
        {
            Mass = checkedMass;
            CenterOfGravityDepth = 0;
            ImpactHeight = 0;
            HeelToeInertia = VerticalInertia = FaceNormalInertia = double.PositiveInfinity;
        }

        /// <summary>
        /// A measured driver head: 204 g, CG 42.3 mm behind the face centre, moments 4085 (heel-toe axis), 5679 (up the
        /// face) and 2843 g cm^2 (face normal), from Table 1 of "Adjusting a Momentum-Based Golf Clubhead-Ball Impact Model
        /// to Improve Accuracy" (University of Waterloo and Ping, Proceedings 2020, 49(1), 47). Which measured axis is which,
        /// and the impact at the CG's projection (the paper's CG is 2.9 and 1 mm off the face normal), are assumptions
        /// (docs/impacts.md).
        /// </summary>
        public static ClubHead MeasuredDriver => new ClubHead(0.204, 0.0423, 0, 4.085e-4, 5.679e-4, 2.843e-4);

        /// <summary>A point-mass head of <paramref name="mass"/> kg (no rotation during the impact).</summary>
        /// <param name="mass">kg; finite and &gt;= 1e-6.</param>
        /// <exception cref="ArgumentException">The mass is outside its range.</exception>
        public static ClubHead PointMass(double mass) => new ClubHead(mass);

        /// <summary>The head's mass, kg.</summary>
        public double Mass { get; }

        /// <summary>The CG's distance behind the impact point along the face normal, m.</summary>
        internal double CenterOfGravityDepth { get; }

        /// <summary>The impact point's distance up the face above the CG's projection on the face, m.</summary>
        internal double ImpactHeight { get; }

        /// <summary>The moment of inertia about the heel-toe axis through the CG, kg m^2 (positive infinity: does not rotate).</summary>
        internal double HeelToeInertia { get; }

        /// <summary>The moment of inertia about the axis up the face through the CG, kg m^2.</summary>
        internal double VerticalInertia { get; }

        /// <summary>The moment of inertia about the face-normal axis through the CG, kg m^2.</summary>
        internal double FaceNormalInertia { get; }

        /// <summary>True when the head cannot rotate under the impact (zero lever, or infinite moments): the point-mass law applies.</summary>
        internal bool IsPointMass =>
            (CenterOfGravityDepth == 0 && ImpactHeight == 0)
            || (double.IsPositiveInfinity(HeelToeInertia) && double.IsPositiveInfinity(VerticalInertia) && double.IsPositiveInfinity(FaceNormalInertia));

        /// <summary>The rigid-body description at an impact with face normal <paramref name="normal"/> and unit up-the-face direction <paramref name="upTheFace"/>.</summary>
        internal RigidBodyInertia Inertia(in Vector3d normal, in Vector3d upTheFace)
        {
            Vector3d heelToe = Vector3d.Cross(normal, upTheFace);
            Vector3d lever = normal * CenterOfGravityDepth + upTheFace * ImpactHeight;
            return new RigidBodyInertia(Mass, lever, heelToe, upTheFace, HeelToeInertia, VerticalInertia, FaceNormalInertia);
        }

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant(
            $"ClubHead({Mass:R} kg, CG {CenterOfGravityDepth * 1000:F1} mm deep, impact {ImpactHeight * 1000:F1} mm above it, I {HeelToeInertia:G4}/{VerticalInertia:G4}/{FaceNormalInertia:G4} kg m^2)");

        private static double RequireMoment(double value, string name)
        {
            if (double.IsPositiveInfinity(value) || (double.IsFinite(value) && value >= MinimumMoment))
            {
                return value;
            }

            throw new ArgumentOutOfRangeException(
                name, value, $"{name} must be >= {Require.Format(MinimumMoment)} kg m^2 (positive infinity: the head does not rotate about that axis); got {Require.Format(value)}.");
        }
    }
}
