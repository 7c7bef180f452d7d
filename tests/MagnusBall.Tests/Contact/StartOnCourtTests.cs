using System;
using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>A bouncing flight whose ball starts touching the court (centre exactly one radius above it).</summary>
    [TestFixture]
    public class StartOnCourtTests
    {
        [TestCase(10.0, 0.0, TestName = "StartTouchingTheCourt_MovingLevel_NeverGoesBelowIt")]
        [TestCase(10.0, -2.0, TestName = "StartTouchingTheCourt_MovingDown_NeverGoesBelowIt")]
        public void StartTouchingTheCourt_NeverGoesBelowIt(double vx, double vz)
        {
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            double r = model.Ball.Radius;
            var court = new Plane(new Vector3d(0, 0, -r), Vector3d.UnitZ); // the centre touches it at z = 0
            var start = new FlightState(Vector3d.Zero, new Vector3d(vx, 0, vz), Vector3d.Zero);
            var flight = Bouncing.Start(model, RungeKutta4.Instance, CrossBounce.Hard, court, start);
            Span<FlightEvent> bounces = stackalloc FlightEvent[4];
            for (int i = 0; i < 1200 && flight.Phase != FlightPhase.Stopped; i++)
            {
                Bouncing.Step(flight, 1.0 / 240, bounces);
                Assert.That(flight.State.Position.Z, Is.GreaterThanOrEqualTo(-1e-12), $"step {i}: {flight.State}");
            }

            Assert.That(flight.Phase, Is.Not.EqualTo(FlightPhase.Flying), "placed on the court and not leaving it, it rolls");
        }
    }
}
