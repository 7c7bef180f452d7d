using System;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests
{
    /// <summary>Normalisation at the ends of the double range: unit vectors for every finite non-zero vector, never NaN.</summary>
    [TestFixture]
    public class Vector3dTests
    {
        [Test]
        public void NormalizedOrZero_OfAVectorWhoseSquareOverflows_IsStillTheUnitVector()
        {
            // |v|^2 = 2.5e401 overflows a double although every component is finite.
            Vector3d unit = new Vector3d(3e200, -4e200, 0).NormalizedOrZero();
            // 1e-15: two roundings of numbers near 1.
            Assert.That(unit.X, Is.EqualTo(0.6).Within(1e-15));
            Assert.That(unit.Y, Is.EqualTo(-0.8).Within(1e-15));
            Assert.That(unit.Z, Is.EqualTo(0));
            Assert.That(new Vector3d(0, 0, double.MaxValue).NormalizedOrZero(), Is.EqualTo(Vector3d.UnitZ));
        }

        [Test]
        public void NormalizedOrZero_OfZeroOrNonFinite_IsZero_NotNaN()
        {
            Assert.That(Vector3d.Zero.NormalizedOrZero(), Is.EqualTo(Vector3d.Zero));
            Assert.That(new Vector3d(double.PositiveInfinity, 1, 0).NormalizedOrZero(), Is.EqualTo(Vector3d.Zero));
            Assert.That(new Vector3d(double.NaN, 1, 0).NormalizedOrZero(), Is.EqualTo(Vector3d.Zero));
        }

        [Test]
        public void LongDirectionVectors_AreAcceptedAsDirections()
        {
            // These passed the non-zero check but used to normalise to zero: no gravity, a plane that is never crossed.
            Assert.That(Gravity.Along(new Vector3d(0, 1e300, 0)), Is.EqualTo(Gravity.YUp));
            Assert.That(new Plane(Vector3d.Zero, new Vector3d(0, 0, 1e300)).Normal, Is.EqualTo(Vector3d.UnitZ));
            Vector3d velocity = new Vector3d(1e200, 0, 0);
            Assert.That(Spin.Topspin(velocity, Vector3d.UnitZ, 10), Is.EqualTo(new Vector3d(0, 10, 0)));
        }
    }
}
