using UnityEngine;
#if ENABLE_INPUT_SYSTEM
using UnityEngine.InputSystem;
#endif

namespace MagnusBall.Samples.TennisScene.Scripts
{
    /// <summary>
    /// Reads the scene's keys through whichever input backend the project has active, as Unity recommends:
    /// the Input System package when ENABLE_INPUT_SYSTEM is defined (Unity 6 templates; reading
    /// UnityEngine.Input there throws InvalidOperationException), otherwise the Input Manager when
    /// ENABLE_LEGACY_INPUT_MANAGER is. With "Both" active the Input System is used.
    /// </summary>
    /// <remarks>
    /// Keys are configured as <see cref="KeyCode"/> in the inspector for both backends; the Input System
    /// path maps letters, digits, F1-F12 and Space to its <c>Key</c> (any other key reads as not pressed).
    /// Nothing allocates.
    /// </remarks>
    public static class SceneInput
    {
        /// <summary>True in the frame the key went down.</summary>
        /// <param name="key">The key.</param>
        public static bool WasPressed(KeyCode key)
        {
#if ENABLE_INPUT_SYSTEM
            Keyboard keyboard = Keyboard.current;
            if (keyboard == null)
            {
                return false; // no keyboard connected
            }

            Key mapped = ToInputSystem(key);
            return mapped != Key.None && keyboard[mapped].wasPressedThisFrame;
#elif ENABLE_LEGACY_INPUT_MANAGER
            return Input.GetKeyDown(key);
#else
            return false;
#endif
        }

#if ENABLE_INPUT_SYSTEM
        /// <summary>The Input System's key for an Input Manager key code (None when not mapped).</summary>
        /// <param name="key">The key code.</param>
        public static Key ToInputSystem(KeyCode key)
        {
            // Both enums number these runs of keys contiguously (UnityCsReference KeyCode.cs; Input System Keyboard.cs).
            int code = (int)key;
            if (key == KeyCode.Space)
            {
                return Key.Space;
            }

            if (code >= (int)KeyCode.A && code <= (int)KeyCode.Z)
            {
                return (Key)((int)Key.A + code - (int)KeyCode.A);
            }

            if (code >= (int)KeyCode.F1 && code <= (int)KeyCode.F12)
            {
                return (Key)((int)Key.F1 + code - (int)KeyCode.F1);
            }

            if (code == (int)KeyCode.Alpha0)
            {
                return Key.Digit0; // the Input System puts 0 after 9, as the keyboard does
            }

            if (code > (int)KeyCode.Alpha0 && code <= (int)KeyCode.Alpha9)
            {
                return (Key)((int)Key.Digit1 + code - (int)KeyCode.Alpha0 - 1);
            }

            return Key.None;
        }
#endif
    }
}
