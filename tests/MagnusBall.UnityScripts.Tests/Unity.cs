using System;
using System.IO;
using System.Reflection;
using MagnusBall.Components;
using MagnusBall.UnityStubs;
using NUnit.Framework;
using UnityEngine;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>Calls scripts the way Unity's player loop does (their messages are private, found by name).</summary>
    internal static class UnityLoop
    {
        /// <summary>Calls a Unity message (Awake, Start, Update, ...) if the script has it.</summary>
        public static void Call(object script, string message, params object[] arguments)
        {
            MethodInfo? method = script.GetType().GetMethod(message, BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public);
            bool fixedUpdate = message == "FixedUpdate";
            StubControl.InFixedUpdate = fixedUpdate; // Time.deltaTime is Time.fixedDeltaTime inside FixedUpdate
            try
            {
                method?.Invoke(script, arguments.Length == 0 ? null : arguments);
            }
            finally
            {
                StubControl.InFixedUpdate = false;
            }
        }

        /// <summary>A message as a delegate: calling it allocates nothing (MethodInfo.Invoke would).</summary>
        public static Action Message(object script, string message)
        {
            var call = (Action)Delegate.CreateDelegate(typeof(Action), script, script.GetType().GetMethod(message, BindingFlags.Instance | BindingFlags.NonPublic)!);
            if (message != "FixedUpdate")
            {
                return call;
            }

            return () =>
            {
                StubControl.InFixedUpdate = true; // Time.deltaTime is Time.fixedDeltaTime inside FixedUpdate
                try
                {
                    call();
                }
                finally
                {
                    StubControl.InFixedUpdate = false;
                }
            };
        }

        /// <summary>AddComponent, then Awake, as Unity does.</summary>
        public static T Add<T>(GameObject holder)
            where T : Component
        {
            T component = holder.AddComponent<T>();
            Call(component, "Awake");
            return component;
        }

        /// <summary>A trajectory preview on a new GameObject with its LineRenderer, awake, following <paramref name="flight"/>.</summary>
        public static MagnusBallTrajectoryPreview AddPreview(MagnusBallFlight flight)
        {
            var holder = new GameObject("line");
            holder.AddComponent<LineRenderer>();
            MagnusBallTrajectoryPreview preview = Add<MagnusBallTrajectoryPreview>(holder);
            preview.flight = flight;
            return preview;
        }

        /// <summary>What Unity does when it loads a component saved before 0.2.0 whose free-text preset field held <paramref name="oldName"/>.</summary>
        public static void LoadOldPreset(FlightSettings settings, string oldName)
        {
            // [FormerlySerializedAs("preset")] puts the old text in the hidden field; then Unity calls OnAfterDeserialize.
            typeof(FlightSettings).GetField("legacyPresetName", BindingFlags.Instance | BindingFlags.NonPublic)!.SetValue(settings, oldName);
            ((ISerializationCallbackReceiver)settings).OnAfterDeserialize();
        }

        /// <summary>The repository root (the folder with MagnusBall.sln).</summary>
        public static string RepositoryRoot()
        {
            for (var directory = new DirectoryInfo(TestContext.CurrentContext.TestDirectory); directory != null; directory = directory.Parent)
            {
                if (File.Exists(Path.Combine(directory.FullName, "MagnusBall.sln")))
                {
                    return directory.FullName;
                }
            }

            throw new InvalidOperationException("MagnusBall.sln not found above the test directory");
        }
    }
}
