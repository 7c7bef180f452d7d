using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// Contact flights give the same bits on every runtime: the net-cord figure's four flights (cord, mesh, bounces on the court),
    /// hashed event by event, against the hash recorded on CoreCLR. The Mono run of these tests (tests/MagnusBall.Tests.Mono)
    /// holds Mono to it (the shapes use only +, -, *, / and square roots).
    /// </summary>
    public class ContactShapeBitsTests
    {
        private const ulong RecordedHash = 0x4095BE4B2A4E9D0EUL;

        [Test]
        public void NetCordFlights_HashToTheRecordedBits()
        {
            ulong hash = 14695981039346656037UL;
            void Add(double value)
            {
                hash ^= (ulong)BitConverter.DoubleToInt64Bits(value);
                hash *= 1099511628211UL;
            }

            void AddVector(in Vector3d v)
            {
                Add(v.X);
                Add(v.Y);
                Add(v.Z);
            }

            foreach (double offset in NetCordFigure.Offsets)
            {
                var events = new List<FlightEvent>();
                List<FlightState> path = NetCordFigure.Path(offset, events);
                foreach (FlightEvent e in events)
                {
                    Add((int)e.Kind);
                    Add(e.ShapeId);
                    Add(e.Time);
                    AddVector(e.Position);
                    AddVector(e.After.Velocity);
                    AddVector(e.After.AngularVelocity);
                    AddVector(e.ContactNormal);
                }

                FlightState last = path[path.Count - 1];
                AddVector(last.Position);
                AddVector(last.Velocity);
            }

            TestContext.Out.WriteLine($"hash 0x{hash:X16}");
            Assert.That(hash, Is.EqualTo(RecordedHash), $"got 0x{hash:X16}");
        }
    }
}
