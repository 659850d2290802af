#pragma once
// OSC 1.0 messages built byte by byte as the specification lays them out (address, type tags
// and arguments, each padded to four bytes, numbers big-endian), and sent over real UDP to
// 127.0.0.1: what a controller app sends, independent of the library that decodes it.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace gridifs::test_support {

class OscPacket {
 public:
  explicit OscPacket(const std::string& address) : address_(address) {}
  OscPacket& f(float v) {
    tags_ += 'f';
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    word(bits);
    return *this;
  }
  OscPacket& i(std::int32_t v) {
    tags_ += 'i';
    word(std::uint32_t(v));
    return *this;
  }
  OscPacket& s(const std::string& v) {
    tags_ += 's';
    padded(args_, v);
    return *this;
  }
  std::vector<char> bytes() const {
    std::vector<char> out;
    padded(out, address_);
    padded(out, tags_);
    out.insert(out.end(), args_.begin(), args_.end());
    return out;
  }

 private:
  static void padded(std::vector<char>& out, const std::string& text) {
    out.insert(out.end(), text.begin(), text.end());
    out.push_back('\0');
    while (out.size() % 4) out.push_back('\0');
  }
  void word(std::uint32_t v) {
    const std::uint32_t big = htonl(v);
    const char* p = reinterpret_cast<const char*>(&big);
    args_.insert(args_.end(), p, p + 4);
  }
  std::string address_, tags_ = ",";
  std::vector<char> args_;
};

/// Sends `datagram` to 127.0.0.1:`port` over UDP; false when it could not be sent.
inline bool sendUdp(int port, const std::vector<char>& datagram) {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (s < 0) return false;
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(std::uint16_t(port));
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const ssize_t n = ::sendto(s, datagram.data(), datagram.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
  ::close(s);
  return n == ssize_t(datagram.size());
}

/// A UDP port on 127.0.0.1 that was free a moment ago (the kernel's choice).
inline int freeUdpPort() {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<const sockaddr*>(&a), sizeof a);
  socklen_t length = sizeof a;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &length);
  ::close(s);
  return ntohs(a.sin_port);
}

}  // namespace gridifs::test_support
